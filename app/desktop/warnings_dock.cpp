#include "app/desktop/warnings_dock.h"

#include <QFontDatabase>
#include <QPlainTextEdit>

#include "app/desktop/desk_model.h"
#include "io/warnings_text.h"

namespace caliper3d::app {

WarningsDock::WarningsDock(const DeskModel& model, QWidget* parent)
    : QDockWidget("Warnings", parent), m_model(model) {
    setObjectName("warnings");
    m_list = new QPlainTextEdit(this);
    m_list->setReadOnly(true);
    // Wrapped to the dock: each warning starts with the file's path, which in a narrow dock
    // would be all one sees of it.
    m_list->setLineWrapMode(QPlainTextEdit::WidgetWidth);
    m_list->setWordWrapMode(QTextOption::WrapAtWordBoundaryOrAnywhere);
    m_list->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    setWidget(m_list);
    connect(&model, &DeskModel::wellsChanged, this, &WarningsDock::refresh);
    // A field's wells change often while they load (their progress): most leave the text as
    // it was, and 100 wells' warnings written again for each was most of a field's load.
    connect(&model, &DeskModel::wellChanged, this, &WarningsDock::refreshWell);
    refresh();
}

QString WarningsDock::text() const {
    return m_list->toPlainText();
}

QString WarningsDock::wellText(int well) const {
    const DeskWell& record = m_model.well(well);
    QString text;
    if (!record.error.isEmpty()) text += "error: " + record.error + "\n";
    return text + QString::fromStdString(io::formatWarnings(record.diagnostics));
}

void WarningsDock::refreshWell(int well) {
    if (well < 0 || static_cast<std::size_t>(well) >= m_texts.size() ||
        m_texts.size() != static_cast<std::size_t>(m_model.wellCount()))
        return refresh();
    if (wellText(well) != m_texts[static_cast<std::size_t>(well)]) refresh();
}

void WarningsDock::refresh() {
    QString text;
    std::size_t count = 0;
    m_texts.clear();
    for (int i = 0; i < m_model.wellCount(); ++i) {
        m_texts.push_back(wellText(i));
        text += m_texts.back();
        count += m_model.well(i).diagnostics.warningCount;
    }
    if (text.isEmpty()) text = m_model.wellCount() > 0 ? "No warnings." : "No well loaded.";
    m_list->setPlainText(text);
    setWindowTitle(count > 0 ? QString("Warnings (%1)").arg(count) : QString("Warnings"));
}

}  // namespace caliper3d::app
