#include "app/desktop/picture_renderer.h"

#include <limits>

#include "app/desktop/desk_model.h"
#include "app/desktop/well_session.h"

namespace caliper3d::app {

scenegraph::PictureRequest windowPictureRequest(const WellSession& session, const SoCamera& camera,
                                                int width, int height) {
    scenegraph::PictureRequest request;
    request.width = width;
    request.height = height;
    request.camera = &camera;
    request.unloggedPath = true;  // the wells whole, as the window shows them
    request.radialExaggeration = session.look().radialExaggeration;
    request.legend = session.legend();
    return request;
}

scenegraph::Picture drawWindowPicture(const WellSession& session, const SoCamera& camera, int width,
                                      int height) {
    const DeskModel& model = session.model();
    scenegraph::PictureRequest request = windowPictureRequest(session, camera, width, height);
    request.tickedWell = std::numeric_limits<std::size_t>::max();  // the current one, if shown
    std::size_t shown = 0;  // the order of session.pictureWells()
    for (int i = 0; i < model.wellCount(); ++i)
        if (model.well(i).geometry && model.well(i).visible) {
            if (i == model.currentWell()) request.tickedWell = shown;
            ++shown;
        }
    return scenegraph::drawPicture(session.pictureWells(), request);
}

}  // namespace caliper3d::app
