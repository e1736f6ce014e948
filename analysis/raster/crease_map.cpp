// Sheet and crease rasterisation; see crease_map.hpp.
#include "analysis/raster/crease_map.hpp"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <map>

namespace crumple::analysis {
namespace {

// Endpoints carry kShift fractional bits so a line starts where the node really is, not at the
// nearest pixel centre; otherwise short edges would be distorted by up to half a pixel.
constexpr int kShift = 4;
constexpr double kScale = 1 << kShift;

cv::Point fixed_point(const MeshData& m, std::int32_t node, const RasterFrame& f) {
  const auto& r = m.ref_positions[static_cast<std::size_t>(node)];
  const cv::Point2d q = f.to_px(r[0], r[1]);
  return {cvRound(q.x * kScale), cvRound(q.y * kScale)};
}

void draw_edge(cv::Mat& img, const MeshData& m, const std::array<std::int32_t, 2>& e,
               const RasterFrame& f, const cv::Scalar& colour, int thickness) {
  cv::line(img, fixed_point(m, e[0], f), fixed_point(m, e[1], f), colour, thickness, cv::LINE_8,
           kShift);
}

}  // namespace

cv::Mat sheet_mask(const MeshData& mesh, const RasterFrame& frame) {
  cv::Mat mask = cv::Mat::zeros(frame.height, frame.width, CV_8U);
  for (const auto& t : mesh.triangles) {
    const cv::Point pts[3] = {fixed_point(mesh, t[0], frame), fixed_point(mesh, t[1], frame),
                              fixed_point(mesh, t[2], frame)};
    cv::fillConvexPoly(mask, pts, 3, cv::Scalar(255), cv::LINE_8, kShift);
  }
  return mask;
}

std::vector<std::array<std::int32_t, 2>> border_edges(const MeshData& mesh) {
  std::map<std::pair<std::int32_t, std::int32_t>, int> count;
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const auto a = t[static_cast<std::size_t>(k)], b = t[static_cast<std::size_t>((k + 1) % 3)];
      ++count[{std::min(a, b), std::max(a, b)}];
    }
  std::vector<std::array<std::int32_t, 2>> out;
  for (const auto& [e, c] : count)
    if (c == 1) out.push_back({e.first, e.second});
  return out;
}

cv::Mat crease_layer(const MeshData& mesh, const std::vector<char>& creased,
                     const RasterFrame& frame, int thickness) {
  cv::Mat img = cv::Mat::zeros(frame.height, frame.width, CV_8U);
  for (std::size_t i = 0; i < creased.size(); ++i)
    if (creased[i])
      draw_edge(img, mesh, mesh.edges[static_cast<std::size_t>(mesh.hinge_edge[i])], frame,
                cv::Scalar(255), thickness);
  return img;
}

cv::Mat crease_map_image(const MeshData& mesh, const std::vector<double>& p,
                         const std::vector<char>& creased, const RasterFrame& frame,
                         int thickness) {
  cv::Mat img(frame.height, frame.width, CV_8UC3, cv::Scalar(255, 255, 255));
  img.setTo(cv::Scalar(225, 225, 225), sheet_mask(mesh, frame));
  for (const auto& e : border_edges(mesh)) draw_edge(img, mesh, e, frame, cv::Scalar(0, 0, 0), 1);
  for (std::size_t i = 0; i < creased.size(); ++i)
    if (creased[i])
      draw_edge(img, mesh, mesh.edges[static_cast<std::size_t>(mesh.hinge_edge[i])], frame,
                p[i] > 0 ? cv::Scalar(40, 40, 220) : cv::Scalar(200, 90, 30), thickness);
  return img;
}

}  // namespace crumple::analysis
