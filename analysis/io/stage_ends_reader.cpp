// /stage_ends reading; see stage_ends_reader.hpp.
#include "analysis/io/stage_ends_reader.hpp"

#include <algorithm>
#include <utility>

namespace crumple::analysis {

void read_stage_ends(const H5::H5File& file, const h5::Reader& r, hsize_t hinges, RunData& run) {
  if (!file.nameExists("stage_ends")) {
    run.warnings.push_back(
        "no /stage_ends group (a run file from before per-stage output): the per-stage crease "
        "lengths are not reported");
    return;
  }
  run.has_stage_ends = true;
  const H5::Group sg = file.openGroup("stage_ends");
  std::vector<std::pair<int, StageEndData>> found;
  for (hsize_t i = 0; i < sg.getNumObjs(); ++i) {
    const std::string name = sg.getObjnameByIdx(i);
    int counter = 0;
    if (sg.getObjTypeByIdx(i) != H5G_GROUP || !h5::parse_counter(name, counter, r, "/stage_ends")) continue;
    const H5::Group g = sg.openGroup(name);
    const std::string where = "/stage_ends/" + name;
    StageEndData s;
    s.p = r.read<double>(g, where, "p", H5::PredType::NATIVE_DOUBLE, hinges, 0);
    r.require_finite(s.p, where + "/p");
    s.t = r.number_attribute<double>(g, where, "t", H5::PredType::NATIVE_DOUBLE);
    s.cycle = r.number_attribute<int>(g, where, "cycle", H5::PredType::NATIVE_INT);
    s.stage_index = r.number_attribute<int>(g, where, "stage_index", H5::PredType::NATIVE_INT);
    s.stage = r.string_attribute(g, where, "stage");
    found.emplace_back(counter, std::move(s));
  }
  // HDF5 lists links in name order already; sorting by the counter's value makes the run
  // order independent of zero padding.
  std::stable_sort(found.begin(), found.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  for (auto& f : found) run.stage_ends.push_back(std::move(f.second));
  if (run.stage_ends.empty())
    run.warnings.push_back("/stage_ends holds no stage records: no per-stage crease lengths");
}

}  // namespace crumple::analysis
