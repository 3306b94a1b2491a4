#pragma once

#include <QTimer>
#include <QWidget>

class QProgressBar;
class QToolButton;

namespace caliper3d::app {

class WellSession;

// The status bar's load progress: a bar with what is being done ("Reading NAME 40%") and a
// Cancel button (Esc), shown while the session loads, polled from it every 100 ms.
class LoadProgressBar : public QWidget {
    Q_OBJECT

public:
    LoadProgressBar(WellSession& session, QWidget* parent);

    QProgressBar* bar() const { return m_bar; }
    // Reads the session's progress now (the timer does so while a load runs).
    void refresh();

private:
    static constexpr int kSteps = 1000;
    static constexpr int kInterval_ms = 100;
    static constexpr int kMaxWidth_px = 480;
    static constexpr int kTextMargin_px = 24;  // the bar's frame and padding around its text
    WellSession& m_session;
    QProgressBar* m_bar = nullptr;
    QToolButton* m_cancel = nullptr;
    QTimer m_timer;
};

}  // namespace caliper3d::app
