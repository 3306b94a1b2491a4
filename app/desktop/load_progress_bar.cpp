#include "app/desktop/load_progress_bar.h"

#include <algorithm>

#include <QFontMetrics>
#include <QHBoxLayout>
#include <QProgressBar>
#include <QToolButton>

#include "app/desktop/well_session.h"

namespace caliper3d::app {

LoadProgressBar::LoadProgressBar(WellSession& session, QWidget* parent)
    : QWidget(parent), m_session(session) {
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    m_bar = new QProgressBar(this);
    m_bar->setRange(0, kSteps);
    m_bar->setMaximumWidth(kMaxWidth_px);
    m_bar->setTextVisible(true);
    m_cancel = new QToolButton(this);
    m_cancel->setText("Cancel");
    m_cancel->setToolTip("Stop loading (Esc); the wells not loaded yet are removed");
    m_cancel->setShortcut(QKeySequence(Qt::Key_Escape));
    layout->addWidget(m_bar);
    layout->addWidget(m_cancel);
    connect(m_cancel, &QToolButton::clicked, &m_session, &WellSession::cancelLoading);
    m_timer.setInterval(kInterval_ms);
    connect(&m_timer, &QTimer::timeout, this, &LoadProgressBar::refresh);
    connect(&m_session, &WellSession::loadStarted, this, [this] {
        m_timer.start();
        refresh();
    });
    connect(&m_session, &WellSession::loadCancelled, this, &LoadProgressBar::refresh);
    connect(&m_session, &WellSession::allWellsLoaded, this, &LoadProgressBar::refresh);
    m_bar->hide();
    m_cancel->hide();
}

void LoadProgressBar::refresh() {
    const LoadProgress progress = m_session.progress();
    m_bar->setVisible(progress.busy);
    m_cancel->setVisible(progress.busy);
    if (!progress.busy) {
        m_timer.stop();
        return;
    }
    m_bar->setValue(static_cast<int>(kSteps * progress.fraction));
    // The whole text in the bar: wide enough for it, a long file name shortened in the middle.
    const QFontMetrics metrics(m_bar->font());
    const int room = kMaxWidth_px - kTextMargin_px;
    const QString text = metrics.elidedText(progress.text + " 100%", Qt::ElideMiddle, room);
    m_bar->setMinimumWidth(
        std::min(kMaxWidth_px, metrics.horizontalAdvance(text) + kTextMargin_px));
    m_bar->setFormat(text.chopped(5) + " %p%");  // " 100%" kept whole by ElideMiddle
}

}  // namespace caliper3d::app
