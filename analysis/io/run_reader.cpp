// HDF5 reading of a run file; see run_reader.hpp. Every dataset is read through the native
// memory type the analysis uses (HDF5 converts stored widths), after its rank and extents are
// checked against the mesh sizes.
#include "analysis/io/run_reader.hpp"

#include <H5Cpp.h>

#include <algorithm>
#include <filesystem>

namespace crumple::analysis {
namespace {

class Reader {
 public:
  explicit Reader(std::string path) : path_(std::move(path)) {}

  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(path_ + ": " + what);
  }

  /// Extents of dataset `name` in `g`, or fail naming it.
  std::vector<hsize_t> dims(const H5::Group& g, const std::string& where,
                            const std::string& name) const {
    if (!g.nameExists(name)) fail("missing dataset " + where + "/" + name);
    H5::DataSet ds = g.openDataSet(name);
    H5::DataSpace sp = ds.getSpace();
    std::vector<hsize_t> d(static_cast<std::size_t>(sp.getSimpleExtentNdims()));
    sp.getSimpleExtentDims(d.data());
    return d;
  }

  /// Reads a dataset of shape (rows) when cols == 0, else (rows, cols); checks the shape.
  template <class T>
  std::vector<T> read(const H5::Group& g, const std::string& where, const std::string& name,
                      const H5::PredType& type, hsize_t rows, hsize_t cols) const {
    const auto d = dims(g, where, name);
    const bool ok = cols == 0 ? (d.size() == 1 && d[0] == rows)
                              : (d.size() == 2 && d[0] == rows && d[1] == cols);
    if (!ok) {
      std::string got;
      for (auto v : d) got += (got.empty() ? "" : ", ") + std::to_string(v);
      fail(where + "/" + name + " has shape (" + got + "), expected (" + std::to_string(rows) +
           (cols ? ", " + std::to_string(cols) : std::string()) + ")");
    }
    std::vector<T> out(static_cast<std::size_t>(rows * std::max<hsize_t>(cols, 1)));
    if (!out.empty()) g.openDataSet(name).read(out.data(), type);
    return out;
  }

  /// Row count of a 2-D dataset with a fixed column count (the count that defines a size).
  hsize_t rows(const H5::Group& g, const std::string& where, const std::string& name,
               hsize_t cols) const {
    const auto d = dims(g, where, name);
    if (d.size() != 2 || d[1] != cols)
      fail(where + "/" + name + " must be 2-D with " + std::to_string(cols) + " columns");
    return d[0];
  }

 private:
  std::string path_;
};

template <std::size_t K, class T>
std::vector<std::array<T, K>> as_rows(const std::vector<T>& flat) {
  std::vector<std::array<T, K>> out(flat.size() / K);
  for (std::size_t i = 0; i < out.size(); ++i)
    std::copy_n(flat.begin() + static_cast<std::ptrdiff_t>(K * i), K, out[i].begin());
  return out;
}

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

/// Cycle groups are named by their number ("0001"); anything else under /cycles is ignored.
bool parse_cycle_name(const std::string& name, int& cycle) {
  if (name.empty() || !std::all_of(name.begin(), name.end(), ::isdigit)) return false;
  cycle = std::stoi(name);
  return true;
}

}  // namespace

RunData read_run(const std::string& path) {
  H5::Exception::dontPrint();
  Reader r(path);
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
      if (!(run.length_unit_m > 0)) r.fail("/meta@length_unit_m must be positive");
    } else {
      run.warnings.push_back("no /meta group; assuming length_unit_m = 1");
    }
    if (file.nameExists("config")) {
      H5::DataSet ds = file.openDataSet("config");
      if (ds.getTypeClass() == H5T_STRING) ds.read(run.config_yaml, ds.getStrType());
      run.config_yaml = run.config_yaml.c_str();
    } else {
      run.warnings.push_back("no /config dataset; compaction unknown");
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
    m.ref_positions = as_rows<3>(r.read<double>(mg, "/mesh", "ref_positions", D, n, 3));
    m.triangles = as_rows<3>(r.read<std::int32_t>(mg, "/mesh", "triangles", I, t, 3));
    m.edges = as_rows<2>(r.read<std::int32_t>(mg, "/mesh", "edges", I, e, 2));
    m.rest_lengths = r.read<double>(mg, "/mesh", "rest_lengths", D, e, 0);
    m.hinges = as_rows<4>(r.read<std::int32_t>(mg, "/mesh", "hinges", I, h, 4));
    m.hinge_edge = r.read<std::int32_t>(mg, "/mesh", "hinge_edge", I, h, 0);
    m.boundary = r.read<std::uint8_t>(mg, "/mesh", "boundary", H5::PredType::NATIVE_UINT8, n, 0);
    if (n < 3 || t < 1) r.fail("/mesh has no triangles");
    for (const auto& tri : m.triangles)
      for (auto v : tri)
        if (v < 0 || static_cast<hsize_t>(v) >= n) r.fail("/mesh/triangles index out of range");
    for (auto he : m.hinge_edge)
      if (he < 0 || static_cast<hsize_t>(he) >= e) r.fail("/mesh/hinge_edge index out of range");
    for (const auto& ed : m.edges)
      for (auto v : ed)
        if (v < 0 || static_cast<hsize_t>(v) >= n) r.fail("/mesh/edges index out of range");

    if (!file.nameExists("cycles")) r.fail("missing group /cycles (no completed cycles)");
    H5::Group cg = file.openGroup("cycles");
    for (hsize_t i = 0; i < cg.getNumObjs(); ++i) {
      const std::string name = cg.getObjnameByIdx(i);
      CycleData c;
      if (cg.getObjTypeByIdx(i) != H5G_GROUP || !parse_cycle_name(name, c.cycle)) continue;
      H5::Group g = cg.openGroup(name);
      const std::string where = "/cycles/" + name;
      c.p = r.read<double>(g, where, "p", D, h, 0);
      r.rows(g, where, "x", 3) == n ? void() : r.fail(where + "/x must have " +
                                                      std::to_string(n) + " rows");
      run.cycles.push_back(std::move(c));
    }
    if (run.cycles.empty()) r.fail("/cycles holds no cycle groups (no completed cycles)");
    std::sort(run.cycles.begin(), run.cycles.end(),
              [](const CycleData& a, const CycleData& b) { return a.cycle < b.cycle; });
  } catch (const H5::Exception& ex) {
    r.fail("HDF5 error: " + ex.getDetailMsg());
  }
  return run;
}

}  // namespace crumple::analysis
