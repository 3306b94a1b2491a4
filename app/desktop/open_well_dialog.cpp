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

// A unit box: "the file's" first (no option), then the units the option takes.
QComboBox* unitBox(const QStringList& units, const QString& chosen, QWidget* parent) {
    auto* box = new QComboBox(parent);
    box->addItem("the file's", QString());
    for (const QString& unit : units) box->addItem(unit, unit);
    box->setCurrentIndex(std::max(0, box->findData(chosen)));
    return box;
}

}  // namespace

OpenWellDialog::OpenWellDialog(const QString& path, const LoadOptions& look, QWidget* parent,
                               const std::optional<OpenChoices>& initial)
    : QDialog(parent), m_path(path), m_look(look) {
    setWindowTitle("Open " + QFileInfo(path).fileName());
    resize(720, 680);
    buildDetected();
    buildForm();
    const OpenChoices start = initial.value_or(OpenChoices{});
    m_radii->setText(start.radii);
    m_diameters->setText(start.diameters);
    m_arms->setValue(start.arms);
    m_depthUnit->setCurrentIndex(std::max(0, m_depthUnit->findData(start.depthUnit)));
    m_radiusUnit->setCurrentIndex(std::max(0, m_radiusUnit->findData(start.radiusUnit)));
    m_bitSize->setText(start.bitSize);
    m_survey->setText(start.survey);
    m_wellhead->setText(start.wellhead);
    m_again = new QTimer(this);
    m_again->setSingleShot(true);
    m_again->setInterval(kDescribeDelay_ms);
    connect(m_again, &QTimer::timeout, this, &OpenWellDialog::describe);
    for (QLineEdit* edit : {m_radii, m_diameters, m_bitSize, m_survey, m_wellhead})
        connect(edit, &QLineEdit::textEdited, m_again, qOverload<>(&QTimer::start));
    for (QComboBox* box : {m_depthUnit, m_radiusUnit})
        connect(box, qOverload<int>(&QComboBox::activated), m_again, qOverload<>(&QTimer::start));
    connect(m_arms, qOverload<int>(&QSpinBox::valueChanged), m_again, qOverload<>(&QTimer::start));
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
    m_curves = new QTableWidget(0, 4, this);
    m_curves->setObjectName("curves");
    m_curves->setHorizontalHeaderLabels({"Curve", "Unit", "Role", "Nulls"});
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

void OpenWellDialog::buildForm() {
    auto* form = new QFormLayout;
    m_radii = new QLineEdit(this);
    m_radii->setObjectName("radii");
    m_radii->setToolTip(
        "Curves holding the arm radii, in arm order (as --radii): R1,R2,... or "
        "one LAS 3 array NAME[]; empty: detected");
    form->addRow("Radius curves", m_radii);
    m_diameters = new QLineEdit(this);
    m_diameters->setObjectName("diameters");
    m_diameters->setToolTip("Curves holding opposite-pad diameters (as --diameters): C1,C2");
    form->addRow("Diameter curves", m_diameters);
    m_arms = new QSpinBox(this);
    m_arms->setObjectName("arms");
    m_arms->setRange(io::kMinArms, io::kMaxArms);
    m_arms->setToolTip("Radii per line of a column-text file (as --arms)");
    form->addRow("Arms (column text)", m_arms);
    m_depthUnit = unitBox({"m", "ft"}, QString(), this);
    m_depthUnit->setObjectName("depthUnit");
    form->addRow("Depth unit", m_depthUnit);
    m_radiusUnit = unitBox({"in", "mm", "cm"}, QString(), this);
    m_radiusUnit->setObjectName("radiusUnit");
    form->addRow("Radius unit", m_radiusUnit);
    m_bitSize = new QLineEdit(this);
    m_bitSize->setObjectName("bitSize");
    m_bitSize->setToolTip(
        "Overrides the log's bit size: 8.5in, 215.9mm (a bare number is "
        "inches); empty: the log's own");
    form->addRow("Bit size", m_bitSize);
    auto* survey = new QHBoxLayout;
    m_survey = new QLineEdit(this);
    m_survey->setObjectName("survey");
    m_survey->setPlaceholderText("none: the path from the log's DEVI/HAZI");
    auto* browse = new QPushButton("Browse...", this);
    connect(browse, &QPushButton::clicked, this, &OpenWellDialog::browseSurvey);
    survey->addWidget(m_survey, 1);
    survey->addWidget(browse);
    form->addRow("Survey", survey);
    m_wellhead = new QLineEdit(this);
    m_wellhead->setObjectName("wellhead");
    m_wellhead->setPlaceholderText("E,N,ELEV in metres, e.g. 512300,6801200,25.5 (none: origin)");
    form->addRow("Wellhead", m_wellhead);
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
    OpenChoices c;
    c.path = m_path;
    c.radii = m_radii->text().trimmed();
    c.diameters = m_diameters->text().trimmed();
    c.arms = m_arms->value();
    c.depthUnit = m_depthUnit->currentData().toString();
    c.radiusUnit = m_radiusUnit->currentData().toString();
    c.bitSize = m_bitSize->text().trimmed();
    c.survey = m_survey->text().trimmed();
    c.wellhead = m_wellhead->text().trimmed();
    return c;
}

void OpenWellDialog::describe() {
    m_again->stop();
    m_info.reset();
    try {
        const OpenChoices chosen = choices();
        m_request = openRequestFrom(chosen, m_look);
        if (!chosen.survey.isEmpty() && !QFileInfo(chosen.survey).isFile())
            throw std::runtime_error(chosen.survey.toStdString() + ": no such survey file");
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
    m_radii->setPlaceholderText("detected: " + text(info.armSource));
    // The arm count is read from column text only; a LAS names its curves.
    m_arms->setEnabled(info.format.rfind("LAS", 0) != 0);
    m_bitSize->setPlaceholderText(std::isfinite(info.bitSize_mm)
                                      ? "the log's: " + bitSizeText(info)
                                      : "none in the log: e.g. 8.5in or 215.9mm");
    m_curves->setRowCount(static_cast<int>(info.curves.size()));
    for (std::size_t i = 0; i < info.curves.size(); ++i) {
        const io::CurveInfo& c = info.curves[i];
        const int row = static_cast<int>(i);
        m_curves->setItem(row, 0, new QTableWidgetItem(text(c.mnemonic)));
        m_curves->setItem(row, 1, new QTableWidgetItem(text(c.unit)));
        m_curves->setItem(row, 2, new QTableWidgetItem(text(c.role)));
        m_curves->setItem(row, 3, new QTableWidgetItem(QString::number(c.nulls)));
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

void OpenWellDialog::browseSurvey() {
    const QString path =
        QFileDialog::getOpenFileName(this, "Deviation survey", QFileInfo(m_path).absolutePath(),
                                     "Surveys (*.txt *.csv *.las *.LAS *.dat);;All files (*)");
    if (path.isEmpty()) return;
    m_survey->setText(path);
    describe();
}

}  // namespace caliper3d::app
