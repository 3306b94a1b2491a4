#pragma once

#include <vector>

#include <QDockWidget>

class QPlainTextEdit;

namespace caliper3d::app {

class DeskModel;

// The warnings met while loading the wells shown (reader, survey, geometry), each with its
// file and line, and why a well failed to load: a pane that stays open beside the view.
class WarningsDock : public QDockWidget {
    Q_OBJECT

public:
    explicit WarningsDock(const DeskModel& model, QWidget* parent = nullptr);
    QString text() const;

private:
    void refresh();
    // Well `well`'s part changed: the text is shown again only when that part's did.
    void refreshWell(int well);
    QString wellText(int well) const;

    const DeskModel& m_model;
    QPlainTextEdit* m_list = nullptr;
    std::vector<QString> m_texts;  // each well's part of the text, as shown
};

}  // namespace caliper3d::app
