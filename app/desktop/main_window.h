#pragma once

#include <array>
#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include <QMainWindow>
#include <QSize>
#include <QTimer>

class QLabel;
class QPushButton;
class QProgressBar;
class SbVec2s;
class SoQtExaminerViewer;
class SoSeparator;

namespace caliper3d::scenegraph {
class ViewOverlay;
}

namespace caliper3d::app {

class DeskModel;
class FileMenu;
class LoadProgressBar;
class ViewMenu;
class WarningsDock;
class WellNavigator;
class WellSession;
class WellViewer;

// The desktop window: it only arranges. An examiner viewer in the centre, the docks around
// it (each a view of the DeskModel), the File and View menus and the Colour-by bar (files of
// commands), the load progress and the warnings in the status bar. The wells shown, their
// loading and their nodes belong to the WellSession; the camera's side of the current depth
// to the WellNavigator.
class MainWindow : public QMainWindow {
    Q_OBJECT

public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    WellSession& session() const { return *m_session; }
    // The wells and the current depth every view follows.
    DeskModel& model() const { return *m_model; }
    SoQtExaminerViewer* viewer() const;
    // The camera's side of the current depth (follow, inside the hole, flight, zones).
    WellNavigator& navigator() const { return *m_navigator; }
    // File menu, recent files, drops, exports, pictures, reports (app/desktop/file_menu.h).
    FileMenu& files() const { return *m_files; }
    ViewMenu& views() const { return *m_views; }
    QProgressBar* loadProgress() const;
    QString statusText() const;
    // Picks the wall at `pixel` of the 3D view (Coin's pixels, origin at the bottom left), as a
    // click does: the section hit becomes the current depth and the direction the current
    // azimuth; the camera stays. False when nothing analysed is there.
    bool pickAt(const SbVec2s& pixel);
    // Whether the wells' labels are placed for the camera, view size and wells as they are now
    // (they are once the camera has rested a poll or two; tests wait for it).
    bool labelsPlaced() const;
    // The view's caption lines: the radial exaggeration, then how many names the labels
    // placed last left out for want of room (when any were).
    std::vector<std::string> caption() const;

protected:
    void closeEvent(QCloseEvent* event) override;

private:
    void buildDocks();
    void buildStatusBar();
    void showLoadError(const QString& name, const QString& message);
    void showWarnings();
    void updateWarningsButton();
    void updateTitle();
    void updateLook();
    // The caption: the radial exaggeration, and `namesLine` below it when not empty.
    void setCaption(const std::string& namesLine);
    // Places the wells' labels for the camera once it has rested a tick of m_labelTimer
    // (polled: the viewer moves the camera on its own as it spins, a resize changes what it
    // sees, and the session re-annotates wells as they load).
    void placeLabelsWhenStill();
    static QSize defaultSize();
    static constexpr QSize kMinimumViewSize{480, 360};
    static constexpr int kLabelPoll_ms = 150;  // the camera rests when unchanged this long
    // While a field loads, once its first picture is drawn: a frame a quarter second at most
    // (WellViewer::limitFrames).
    static constexpr std::chrono::milliseconds kFieldLoadFrame{250};
    static constexpr float kLabelRoom_px = 90.0f;   // a depth label right of a well
    static constexpr float kNameOffset_px = 25.0f;  // a well's name from its path
    static constexpr float kBold = 1.08f;           // DejaVu Sans Bold's width over Book's

    DeskModel* m_model = nullptr;
    WellViewer* m_viewer = nullptr;
    SoSeparator* m_viewRoot = nullptr;  // the viewer's graph: the session's scene, the overlay
    std::unique_ptr<scenegraph::ViewOverlay> m_overlay;  // north arrow, radial exaggeration
    WellSession* m_session = nullptr;
    WellNavigator* m_navigator = nullptr;
    QTimer m_labelTimer;
    // The camera, the view's size, the session's annotations and the inside look as last
    // seen, and as the labels were placed for.
    using LabelKey = std::array<double, 12>;
    LabelKey labelKey() const;  // null camera: all zeros
    LabelKey m_labelsSeen{};
    LabelKey m_labelsPlaced{};
    std::string m_namesLine;  // how many names the last placement left out (namesLeftOutCaption)
    FileMenu* m_files = nullptr;
    ViewMenu* m_views = nullptr;
    WarningsDock* m_warningsDock = nullptr;
    LoadProgressBar* m_progress = nullptr;
    QLabel* m_status = nullptr;
    QPushButton* m_warningsButton = nullptr;  // "N warnings": opens the list
};

}  // namespace caliper3d::app
