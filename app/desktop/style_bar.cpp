#include "app/desktop/style_bar.h"

#include <algorithm>

#include <QComboBox>
#include <QLabel>

#include "app/desktop/well_session.h"

namespace caliper3d::app {

StyleBar::StyleBar(WellSession& session, QWidget* parent)
    : QToolBar("Style", parent), m_session(session) {
    setObjectName("style");
    addWidget(new QLabel(" Colour by ", this));
    m_box = new QComboBox(this);
    m_box->setObjectName("colourBy");
    m_box->setToolTip("What the wall's colours show (the legend says how)");
    addWidget(m_box);
    refill();
    connect(m_box, QOverload<int>::of(&QComboBox::activated), this, [this](int index) {
        reconstruction::ColourRequest colour;
        colour.quantity = m_box->itemText(index).toStdString();
        if (!m_session.restyle(m_session.look().radialExaggeration, colour)) refill();
    });
    connect(&m_session, &WellSession::lookChanged, this, &StyleBar::refill);
}

void StyleBar::refill() {
    const QSignalBlocker block(m_box);
    m_box->clear();
    for (const std::string& name : m_session.colourQuantities())
        m_box->addItem(QString::fromStdString(name));
    const int current = m_box->findText(QString::fromStdString(m_session.look().colour.quantity),
                                        Qt::MatchFixedString);
    m_box->setCurrentIndex(std::max(current, 0));
}

}  // namespace caliper3d::app
