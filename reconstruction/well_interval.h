#pragma once

#include <memory>

#include "reconstruction/well_geometry.h"

namespace caliper3d::reconstruction {

// The rows of `whole` with measured depths in [top_m, bottom_m] as a geometry of their own,
// built with `options` (e.g. another radial exaggeration), each row placed exactly where
// `whole` places it (GeometryOptions::continueFrom; a survey places rows by depth alone).
// Its segments start at the interval's first row; it is coloured by departure from bit size
// (GeometryOptions::colouring, one value per row of a table, is not carried over: colour it
// with WellGeometry::restyled). Throws std::invalid_argument when the interval holds fewer
// than two rows.
std::shared_ptr<const WellGeometry> intervalGeometry(const WellGeometry& whole, double top_m,
                                                     double bottom_m, GeometryOptions options);

}  // namespace caliper3d::reconstruction
