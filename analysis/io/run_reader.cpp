// HDF5 reading of a run file; see run_reader.hpp. Every dataset is read through the
// shape-checked helpers of io/h5_checked.hpp, against the mesh sizes.
#include "analysis/io/run_reader.hpp"

#include "analysis/io/h5_checked.hpp"
#include "analysis/io/stage_ends_reader.hpp"

#include <H5Cpp.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace crumple::analysis {
namespace {

/// Scalar attributes of /meta as JSON values; arrays and odd types are skipped.
nlohmann::json read_attributes(const H5::Group& g) {
  nlohmann::json out = nlohmann::json::object();
  for (int i = 0; i < g.getNumAttrs(); ++i) {
    H5::Attribute a = g.openAttribute(static_cast<unsigned>(i));
    if (a.getSpace().getSimpleExtentNpoints() != 1) continue;
    switch (a.getTypeClass()) {
      case H5T_STRING: {
        std::string s;
        a.read(a.getStrType(), s);
        out[a.getName()] = s.c_str();  // drop trailing NULs of fixed-length strings
        break;
      }
      case H5T_FLOAT: {
        double v = 0;
        a.read(H5::PredType::NATIVE_DOUBLE, &v);
        out[a.getName()] = v;
        break;
      }
      case H5T_INTEGER: {
        long long v = 0;
        a.read(H5::PredType::NATIVE_LLONG, &v);
        out[a.getName()] = v;
        break;
      }
      default:
        break;
    }
  }
  return out;
}

}  // namespace

RunData read_run(const std::string& path) {
  H5::Exception::dontPrint();
  const h5::Reader r(path);
  if (!std::filesystem::is_regular_file(path)) r.fail("no such file");
  try {
    if (!H5::H5File::isHdf5(path)) r.fail("not an HDF5 file");
  } catch (const H5::Exception&) {
    r.fail("not an HDF5 file");
  }
  RunData run;
  run.path = path;
  try {
    H5::H5File file(path, H5F_ACC_RDONLY);
    if (file.nameExists("meta")) {
      run.meta = read_attributes(file.openGroup("meta"));
      if (run.meta.contains("length_unit_m") && run.meta["length_unit_m"].is_number())
        run.length_unit_m = run.meta["length_unit_m"].get<double>();
      // A sheet is between a micrometre and a few metres across in any unit system a run can
      // use; outside that the value is damage, and the raster would not fit in memory.
      if (!(run.length_unit_m >= 1e-9 && run.length_unit_m <= 1e3))
        r.fail("/meta@length_unit_m = " + h5::format_number(run.length_unit_m) +
               " is outside [1e-9, 1e3] metres per unit");
    } else {
      run.warnings.push_back("no /meta group; assuming length_unit_m = 1");
    }
    if (file.nameExists("config")) {
      H5::DataSet ds = file.openDataSet("config");
      if (ds.getTypeClass() == H5T_STRING) ds.read(run.config_yaml, ds.getStrType());
      run.config_yaml = run.config_yaml.c_str();
    } else {
      run.warnings.push_back("no /config dataset; yield curvature c0 unknown");
    }

    if (!file.nameExists("mesh")) r.fail("missing group /mesh");
    H5::Group mg = file.openGroup("mesh");
    const auto& I = H5::PredType::NATIVE_INT32;
    const auto& D = H5::PredType::NATIVE_DOUBLE;
    MeshData& m = run.mesh;
    const hsize_t n = r.rows(mg, "/mesh", "ref_positions", 3);
    const hsize_t t = r.rows(mg, "/mesh", "triangles", 3);
    const hsize_t e = r.rows(mg, "/mesh", "edges", 2);
    const hsize_t h = r.rows(mg, "/mesh", "hinges", 4);
    m.ref_positions = h5::as_rows<3>(r.read<double>(mg, "/mesh", "ref_positions", D, n, 3));
    m.triangles = h5::as_rows<3>(r.read<std::int32_t>(mg, "/mesh", "triangles", I, t, 3));
    m.edges = h5::as_rows<2>(r.read<std::int32_t>(mg, "/mesh", "edges", I, e, 2));
    m.rest_lengths = r.read<double>(mg, "/mesh", "rest_lengths", D, e, 0);
    m.hinges = h5::as_rows<4>(r.read<std::int32_t>(mg, "/mesh", "hinges", I, h, 4));
    m.hinge_edge = r.read<std::int32_t>(mg, "/mesh", "hinge_edge", I, h, 0);
    m.boundary = r.read<std::uint8_t>(mg, "/mesh", "boundary", H5::PredType::NATIVE_UINT8, n, 0);
    if (n < 3 || t < 1) r.fail("/mesh has no triangles");
    r.require_finite(h5::flat(m.ref_positions), "/mesh/ref_positions");
    r.require_finite(m.rest_lengths, "/mesh/rest_lengths");
    r.require_indices(m.triangles, n, "/mesh/triangles");
    r.require_indices(m.edges, n, "/mesh/edges");
    r.require_indices(m.hinges, n, "/mesh/hinges");
    for (std::size_t i = 0; i < m.hinge_edge.size(); ++i)
      if (m.hinge_edge[i] < 0 || static_cast<hsize_t>(m.hinge_edge[i]) >= e)
        r.fail("/mesh/hinge_edge row " + std::to_string(i) + " holds edge " +
               std::to_string(m.hinge_edge[i]) + ", outside [0, " + std::to_string(e) + ")");

    if (!file.nameExists("cycles")) r.fail("missing group /cycles (no completed cycles)");
    H5::Group cg = file.openGroup("cycles");
    for (hsize_t i = 0; i < cg.getNumObjs(); ++i) {
      const std::string name = cg.getObjnameByIdx(i);
      CycleData c;
      if (cg.getObjTypeByIdx(i) != H5G_GROUP || !h5::parse_counter(name, c.cycle, r, "/cycles"))
        continue;
      H5::Group g = cg.openGroup(name);
      const std::string where = "/cycles/" + name;
      c.p = r.read<double>(g, where, "p", D, h, 0);
      r.require_finite(c.p, where + "/p");
      r.rows(g, where, "x", 3) == n ? void() : r.fail(where + "/x must have " +
                                                      std::to_string(n) + " rows");
      // The compaction ratio is final / initial gap: NaN (no compacting stage) or in (0, 1].
      if (g.attrExists("compaction")) {
        c.compaction_recorded = true;
        const double d = r.number_attribute<double>(g, where, "compaction", D);
        if (!std::isnan(d)) {
          if (!(d > 0 && d <= 1))
            r.fail(where + "@compaction = " + h5::format_number(d) + " is outside (0, 1]");
          c.compaction = d;
        }
      }
      run.cycles.push_back(std::move(c));
    }
    if (run.cycles.empty()) r.fail("/cycles holds no cycle groups (no completed cycles)");
    std::sort(run.cycles.begin(), run.cycles.end(),
              [](const CycleData& a, const CycleData& b) { return a.cycle < b.cycle; });
    read_stage_ends(file, r, h, run);
  } catch (const H5::Exception& ex) {
    r.fail("HDF5 error: " + ex.getDetailMsg());
  }
  return run;
}

}  // namespace crumple::analysis
