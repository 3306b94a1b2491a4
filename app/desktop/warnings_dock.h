#pragma once

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

    const DeskModel& m_model;
    QPlainTextEdit* m_list = nullptr;
};

}  // namespace caliper3d::app
