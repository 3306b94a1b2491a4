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
    connect(&model, &DeskModel::wellChanged, this, &WarningsDock::refresh);
    refresh();
}

QString WarningsDock::text() const {
    return m_list->toPlainText();
}

void WarningsDock::refresh() {
    QString text;
    std::size_t count = 0;
    for (int i = 0; i < m_model.wellCount(); ++i) {
        const DeskWell& well = m_model.well(i);
        if (!well.error.isEmpty()) text += "error: " + well.error + "\n";
        text += QString::fromStdString(io::formatWarnings(well.diagnostics));
        count += well.diagnostics.warningCount;
    }
    if (text.isEmpty()) text = m_model.wellCount() > 0 ? "No warnings." : "No well loaded.";
    m_list->setPlainText(text);
    setWindowTitle(count > 0 ? QString("Warnings (%1)").arg(count) : QString("Warnings"));
}

}  // namespace caliper3d::app
