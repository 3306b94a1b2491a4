#pragma once

#include <QToolBar>

class QComboBox;

namespace caliper3d::app {

class WellSession;

// The "Colour by" tool bar: the quantities the wall can be coloured by (the built-in ones and
// the first well's curves), the current one chosen; a choice restyles every well.
class StyleBar : public QToolBar {
    Q_OBJECT

public:
    StyleBar(WellSession& session, QWidget* parent);

    // Refills the box from the session (its wells' curves, the colouring they are drawn with).
    void refill();

private:
    WellSession& m_session;
    QComboBox* m_box = nullptr;
};

}  // namespace caliper3d::app
