// Rasterisation of the sheet and its creases in the flat reference frame: the
// sheet mask (all reference triangles filled), the crease layer (crease edges as lines) and the
// colour crease map written as crease_NNNN.png. Drawing uses OpenCV with sub-pixel endpoints.
#pragma once

#include "analysis/io/run_data.hpp"
#include "analysis/raster/raster_frame.hpp"

#include <opencv2/core.hpp>

#include <array>
#include <vector>

namespace crumple::analysis {

/// CV_8U image, 255 inside the sheet (union of the filled reference triangles), 0 outside.
cv::Mat sheet_mask(const MeshData& mesh, const RasterFrame& frame);

/// Edges on the sheet border (edges of exactly one triangle), as node pairs.
std::vector<std::array<std::int32_t, 2>> border_edges(const MeshData& mesh);

/// CV_8U image, 255 on the edges of the hinges flagged in `creased` (h flags), drawn as
/// 8-connected lines `thickness` pixels wide; 8-connected lines keep 4-connected regions apart.
cv::Mat crease_layer(const MeshData& mesh, const std::vector<char>& creased,
                     const RasterFrame& frame, int thickness = 1);

/// Colour map for people: sheet light grey, outline black, creases with p > 0 (one fold sense)
/// red and p < 0 blue. `p` and `creased` are h long.
cv::Mat crease_map_image(const MeshData& mesh, const std::vector<double>& p,
                         const std::vector<char>& creased, const RasterFrame& frame,
                         int thickness = 1);

}  // namespace crumple::analysis
