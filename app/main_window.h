#pragma once

#include <memory>
#include <string>

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

    void openWell(const QString& path, const InputOptions& options);
    SoQtExaminerViewer* viewer() const { return m_viewer; }
    bool loading() const;

signals:
    void wellLoaded(int segments);
    void wellFailed(const QString& message);

private:
    void buildMenus();
    void openDialog();
    void exportDialog();
    void setView(int direction);
    void setExaggeration(double factor);

    SoQtExaminerViewer* m_viewer = nullptr;
    SoSeparator* m_sceneRoot = nullptr;
    QLabel* m_status = nullptr;
    InputOptions m_lastOptions;
    QString m_lastPath;
    std::unique_ptr<scenegraph::WellScene> m_well;
    std::unique_ptr<reconstruction::WellLoadPipeline> m_pipeline;
    std::unique_ptr<scenegraph::SegmentFeeder> m_feeder;
    bool m_viewedAll = false;
};

}  // namespace caliper3d::app
