#pragma once

#include <memory>
#include <string>
#include <vector>

#include <QMainWindow>

#include "app/input_options.h"

class QLabel;
class SoQtExaminerViewer;
class SoSeparator;

namespace caliper3d::reconstruction {
class WellLoadPipeline;
}
namespace caliper3d::scenegraph {
class SegmentFeeder;
class WellScene;
}  // namespace caliper3d::scenegraph

namespace caliper3d::app {

// The desktop window: an SoQtExaminerViewer in the centre, a status bar that
// reports loading, and File/View menus. Wells load on a worker thread; their
// segments enter the scene through the SegmentFeeder's timer sensor on this
// (the main) thread, so the window stays responsive while a well loads.
class MainWindow : public QMainWindow {
    Q_OBJECT

public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    // Replaces the wells shown by this one; its wellhead (if any) becomes the
    // scene origin.
    void openWell(const WellSource& well, const InputOptions& options);
    void openWell(const QString& path, const InputOptions& options);
    // Adds a well to those shown; each loads on its own worker.
    void addWell(const WellSource& well, const InputOptions& options);
    void addWell(const QString& path, const InputOptions& options);
    std::size_t wellCount() const { return m_wells.size(); }
    SoQtExaminerViewer* viewer() const { return m_viewer; }
    bool loading() const;

signals:
    void wellLoaded(int segments);  // once per well
    void allWellsLoaded();
    void wellFailed(const QString& message);

private:
    void buildMenus();
    void openDialog(bool add);
    void exportDialog();
    void setView(int direction);
    void setExaggeration(double factor);

    SoQtExaminerViewer* m_viewer = nullptr;
    SoSeparator* m_sceneRoot = nullptr;
    QLabel* m_status = nullptr;
    InputOptions m_lastOptions;
    reconstruction::Wellhead m_origin;  // the first well's wellhead
    // One well being shown: its nodes, and while it loads its worker and feeder.
    // Members are destroyed feeder first, then the worker, then the nodes.
    struct Well {
        WellSource source;
        InputOptions options;
        std::unique_ptr<scenegraph::WellScene> scene;
        std::unique_ptr<reconstruction::WellLoadPipeline> pipeline;
        std::unique_ptr<scenegraph::SegmentFeeder> feeder;
        bool done = false;
    };
    void wellDone();
    std::vector<std::unique_ptr<Well>> m_wells;
    bool m_viewedAll = false;
};

}  // namespace caliper3d::app
