#include "app/desktop/open_well_dialog.h"

#include <cmath>
#include <exception>

#include <QApplication>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QTableWidget>
#include <QTimer>
#include <QVBoxLayout>

#include "io/log_reader.h"
#include "reconstruction/path/north_reference.h"

namespace caliper3d::app {

namespace {

constexpr int kDescribeDelay_ms = 400;

QString text(const std::string& s) {
    return QString::fromStdString(s);
}

QString bitSizeText(const io::LogInfo& info) {
    if (!std::isfinite(info.bitSize_mm)) return "none in the log";
    auto one = [](double mm) {
        return QString("%1 mm (%2 in)").arg(mm, 0, 'f', 1).arg(mm / 25.4, 0, 'f', 3);
    };
    if (std::isfinite(info.bitSizeMax_mm) && info.bitSizeMax_mm > info.bitSize_mm)
        return one(info.bitSize_mm) + " to " + one(info.bitSizeMax_mm);
    return one(info.bitSize_mm);
}

// The widget's objectName: the option's name in camelCase ("bit-size": "bitSize").
QString objectNameOf(const WellOption& option) {
    QString name;
    bool upper = false;
    for (const QChar c : QString(option.name)) {
        if (c == '-') {
            upper = true;
            continue;
        }
        name += upper ? c.toUpper() : c;
        upper = false;
    }
    return name;
}

}  // namespace

OpenWellDialog::OpenWellDialog(const QString& path, const LoadOptions& look, QWidget* parent,
                               const std::optional<OpenChoices>& initial)
    : QDialog(parent), m_path(path), m_look(look) {
    setWindowTitle("Open " + QFileInfo(path).fileName());
    resize(720, 680);
    buildDetected();
    buildForm();
    // A recent file's texts; one without a field here is kept for choices() as it was.
    m_unshown = initial ? initial->options : OptionTexts();
    for (const Field& field : m_fields) {
        const auto given = m_unshown.find(field.option->name);
        field.setText(given == m_unshown.end() ? QString() : QString::fromStdString(given->second));
        if (given != m_unshown.end()) m_unshown.erase(given);
    }
    m_again = new QTimer(this);
    m_again->setSingleShot(true);
    m_again->setInterval(kDescribeDelay_ms);
    connect(m_again, &QTimer::timeout, this, &OpenWellDialog::describe);
    for (const Field& field : m_fields) {
        if (field.edit)
            connect(field.edit, &QLineEdit::textEdited, m_again, qOverload<>(&QTimer::start));
        if (field.box)
            connect(field.box, qOverload<int>(&QComboBox::activated), m_again,
                    qOverload<>(&QTimer::start));
        if (field.spin)
            connect(field.spin, qOverload<int>(&QSpinBox::valueChanged), m_again,
                    qOverload<>(&QTimer::start));
    }
    describe();
}

void OpenWellDialog::buildDetected() {
    auto* layout = new QVBoxLayout(this);
    auto* file = new QLabel("<b>" + m_path.toHtmlEscaped() + "</b>", this);
    file->setTextInteractionFlags(Qt::TextSelectableByMouse);
    file->setWordWrap(true);
    layout->addWidget(file);
    m_summary = new QLabel(this);
    m_summary->setObjectName("summary");
    m_summary->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_summary->setWordWrap(true);
    layout->addWidget(m_summary);
    m_curves = new QTableWidget(0, 5, this);
    m_curves->setObjectName("curves");
    m_curves->setHorizontalHeaderLabels({"Curve", "Unit", "Role", "Nulls", "Description"});
    m_curves->horizontalHeader()->setStretchLastSection(true);
    m_curves->verticalHeader()->hide();
    m_curves->verticalHeader()->setDefaultSectionSize(fontMetrics().height() + 6);
    m_curves->setEditTriggers(QAbstractItemView::NoEditTriggers);
    layout->addWidget(m_curves, 1);
    m_error = new QLabel(this);
    m_error->setObjectName("error");
    m_error->setWordWrap(true);
    m_error->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_error->setStyleSheet("color: #c0392b;");
    m_error->hide();
    layout->addWidget(m_error);
}

QWidget* OpenWellDialog::Field::widget() const {
    if (edit) return edit;
    if (box) return box;
    return spin;
}

QString OpenWellDialog::Field::text() const {
    if (edit) return edit->text().trimmed();
    if (box) return box->currentData().toString();
    return QString::number(spin->value());
}

void OpenWellDialog::Field::setText(const QString& text) const {
    if (edit) edit->setText(text);
    if (box) box->setCurrentIndex(std::max(0, box->findData(text)));
    // A count is never empty: its blank is the default it starts from.
    if (spin)
        spin->setValue(text.isEmpty() ? QString::fromStdString(option->blank).toInt()
                                      : text.toInt());
}

// A field for each option of the table that names one, in the table's order.
void OpenWellDialog::buildForm() {
    auto* form = new QFormLayout;
    for (const WellOption& option : wellOptions()) {
        if (option.field.empty()) continue;
        Field field;
        field.option = &option;
        const QString blank = QString::fromStdString(option.blank);
        if (option.value == OptionValue::Choice) {
            field.box = new QComboBox(this);
            field.box->addItem(blank, QString());
            for (const std::string& choice : option.choices)
                field.box->addItem(QString::fromStdString(choice), QString::fromStdString(choice));
        } else if (option.value == OptionValue::Count) {
            field.spin = new QSpinBox(this);
            field.spin->setRange(option.minCount, option.maxCount);
        } else {
            field.edit = new QLineEdit(this);
            field.edit->setPlaceholderText(blank);
        }
        QWidget* widget = field.widget();
        widget->setObjectName(objectNameOf(option));
        widget->setToolTip(QString("%1 (as --%2)").arg(option.help, option.name));
        const QString label = QString::fromStdString(option.field);
        if (option.value == OptionValue::Path) {
            auto* row = new QHBoxLayout;
            auto* browse = new QPushButton("Browse...", this);
            connect(browse, &QPushButton::clicked, this, [this, field] { this->browse(field); });
            row->addWidget(widget, 1);
            row->addWidget(browse);
            form->addRow(label, row);
        } else {
            form->addRow(label, widget);
        }
        m_fields.push_back(field);
    }
    auto* layout = static_cast<QVBoxLayout*>(this->layout());
    layout->addLayout(form);
    m_buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(m_buttons, &QDialogButtonBox::accepted, this, [this] {
        describe();  // edits the timer has not caught up with yet
        if (acceptable()) accept();
    });
    connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(m_buttons);
}

OpenChoices OpenWellDialog::choices() const {
    OpenChoices c{m_path, m_unshown};
    for (const Field& field : m_fields) {
        const QString text = field.text();
        if (!text.isEmpty()) c.options[field.option->name] = text.toStdString();
    }
    return c;
}

void OpenWellDialog::describe() {
    m_again->stop();
    m_info.reset();
    try {
        m_request = openRequestFrom(choices(), m_look);
        // A file named in a field is checked here, before the log is read.
        for (const Field& field : m_fields)
            if (field.option->value == OptionValue::Path && !field.text().isEmpty() &&
                !QFileInfo(field.text()).isFile())
                throw std::runtime_error((field.text() + ": no such " +
                                          QString::fromStdString(field.option->field).toLower() +
                                          " file")
                                             .toStdString());
        // The log as read with these options, but its own bit size: the override is shown in
        // its field, the log's beside it.
        io::ReadOptions read = m_request.options.read;
        read.bitSize_mm.reset();
        QApplication::setOverrideCursor(Qt::WaitCursor);
        try {
            m_info = io::describeLog(m_path.toStdString(), read);
        } catch (...) {
            QApplication::restoreOverrideCursor();
            throw;
        }
        QApplication::restoreOverrideCursor();
        // Which north its azimuths are from, with these options (docs/conventions.md, "North").
        const reconstruction::NorthCorrection north =
            reconstruction::resolveNorth(m_info->north, m_info->location, read);
        m_info->north.resolved = north.summary;
        for (const std::string& warning : north.warnings)
            m_info->diagnostics.warn(m_path.toStdString(), 0, warning);
        if (m_info->survey)
            throw std::runtime_error(m_path.toStdString() +
                                     ": a deviation survey, not a caliper log: open the log "
                                     "and give this file as its survey");
        showInfo();
    } catch (const std::exception& e) {
        showError(QString::fromStdString(e.what()));
    }
}

void OpenWellDialog::showInfo() {
    const io::LogInfo& info = *m_info;
    QString summary;
    summary += "Format: " + text(info.format).toHtmlEscaped() + "<br>";
    if (!info.wellName.empty()) summary += "Well: " + text(info.wellName).toHtmlEscaped() + "<br>";
    summary += QString("Rows: %1 sections, depth %2 to %3 m, step %4 m")
                   .arg(info.rows)
                   .arg(info.top_m, 0, 'f', 2)
                   .arg(info.bottom_m, 0, 'f', 2)
                   .arg(info.step_m, 0, 'f', 4);
    if (!info.depthUnit.empty())
        summary += " (file unit " + text(info.depthUnit).toHtmlEscaped() + ")";
    summary += QString("<br>Arms: %1 from %2<br>").arg(info.arms).arg(text(info.armSource));
    summary += "Bit size in the log: " + bitSizeText(info) + "<br>";
    if (!info.holeAzimuth.empty())
        summary += "Hole azimuth: " + text(info.holeAzimuth).toHtmlEscaped() + "<br>";
    if (!info.north.resolved.empty())
        summary += "North: " + text(info.north.resolved).toHtmlEscaped() + "<br>";
    summary += QString("Warnings: %1").arg(info.diagnostics.warningCount);
    constexpr std::size_t kWarningsShown = 4;
    for (std::size_t i = 0; i < info.diagnostics.warnings.size() && i < kWarningsShown; ++i) {
        const io::Warning& w = info.diagnostics.warnings[i];
        summary += "<br>&nbsp;&nbsp;" + (w.line ? QString("line %1: ").arg(w.line) : QString()) +
                   text(w.message).toHtmlEscaped();
    }
    if (info.diagnostics.warningCount > kWarningsShown)
        summary += QString("<br>&nbsp;&nbsp;... and %1 more")
                       .arg(info.diagnostics.warningCount - kWarningsShown);
    m_summary->setText(summary);
    for (const Field& field : m_fields) {
        // The arm count is read from column text only; a LAS names its curves.
        if (field.option->columnTextOnly)
            field.widget()->setEnabled(info.format.rfind("LAS", 0) != 0);
        if (field.edit && field.option->blankFor)
            field.edit->setPlaceholderText(QString::fromStdString(field.option->blankFor(info)));
    }
    m_curves->setRowCount(static_cast<int>(info.curves.size()));
    for (std::size_t i = 0; i < info.curves.size(); ++i) {
        const io::CurveInfo& c = info.curves[i];
        const int row = static_cast<int>(i);
        m_curves->setItem(row, 0, new QTableWidgetItem(text(c.mnemonic)));
        m_curves->setItem(row, 1, new QTableWidgetItem(text(c.unit)));
        m_curves->setItem(row, 2, new QTableWidgetItem(text(c.role)));
        m_curves->setItem(row, 3, new QTableWidgetItem(QString::number(c.nulls)));
        m_curves->setItem(row, 4, new QTableWidgetItem(text(c.description)));
    }
    m_curves->resizeColumnsToContents();
    m_error->clear();
    m_error->hide();
    m_buttons->button(QDialogButtonBox::Ok)->setEnabled(true);
}

void OpenWellDialog::showError(const QString& message) {
    m_error->setText(message);
    m_error->show();
    m_buttons->button(QDialogButtonBox::Ok)->setEnabled(false);
}

QString OpenWellDialog::errorText() const {
    return m_error->text();
}

bool OpenWellDialog::acceptable() const {
    return m_buttons->button(QDialogButtonBox::Ok)->isEnabled();
}

void OpenWellDialog::browse(const Field& field) {
    const QString path = QFileDialog::getOpenFileName(
        this, QString::fromStdString(field.option->field), QFileInfo(m_path).absolutePath(),
        "Surveys (*.txt *.csv *.las *.LAS *.dat);;All files (*)");
    if (path.isEmpty()) return;
    field.setText(path);
    describe();
}

}  // namespace caliper3d::app
