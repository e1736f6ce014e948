// Shape-checked HDF5 reads shared by the run-file readers (io/run_reader.cpp,
// io/stage_ends_reader.cpp); internal to the analysis library.
//
// Every dataset is read through the native memory type the analysis uses (HDF5 converts stored
// widths) after its rank and extents are checked, and every failure is an InputError naming the
// file and the object, so crumple-analyze can exit with code 2 before writing anything.
#pragma once

#include "analysis/io/run_reader.hpp"

#include <H5Cpp.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

namespace crumple::analysis::h5 {

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

  /// Fails naming the dataset when a value read from it is NaN or infinite: every number the
  /// analysis reads from a run file is a position, length or curvature, and a non-finite one
  /// would pass through the rasteriser and the fits as garbage.
  void require_finite(const std::vector<double>& values, const std::string& dataset) const {
    const auto bad = std::find_if(values.begin(), values.end(),
                                  [](double v) { return !std::isfinite(v); });
    if (bad == values.end()) return;
    const auto count = std::count_if(bad, values.end(), [](double v) { return !std::isfinite(v); });
    fail(dataset + " holds " + std::to_string(count) + " non-finite value" +
         (count == 1 ? "" : "s") + " (first at element " +
         std::to_string(bad - values.begin()) + ")");
  }

  /// Fails naming the dataset when an index read from it is outside [0, size).
  template <std::size_t K>
  void require_indices(const std::vector<std::array<std::int32_t, K>>& rows, std::size_t size,
                       const std::string& dataset) const {
    for (std::size_t i = 0; i < rows.size(); ++i)
      for (auto v : rows[i])
        if (v < 0 || static_cast<std::size_t>(v) >= size)
          fail(dataset + " row " + std::to_string(i) + " holds index " + std::to_string(v) +
               ", outside [0, " + std::to_string(size) + ")");
  }

  /// Row count of a 2-D dataset with a fixed column count (the count that defines a size).
  hsize_t rows(const H5::Group& g, const std::string& where, const std::string& name,
               hsize_t cols) const {
    const auto d = dims(g, where, name);
    if (d.size() != 2 || d[1] != cols)
      fail(where + "/" + name + " must be 2-D with " + std::to_string(cols) + " columns");
    return d[0];
  }

  /// Scalar attribute `name` of `g` read as T (a numeric type), or fail naming it.
  template <class T>
  T number_attribute(const H5::Group& g, const std::string& where, const std::string& name,
                     const H5::PredType& type) const {
    if (!g.attrExists(name)) fail("missing attribute " + where + "@" + name);
    H5::Attribute a = g.openAttribute(name);
    if (a.getSpace().getSimpleExtentNpoints() != 1 ||
        (a.getTypeClass() != H5T_INTEGER && a.getTypeClass() != H5T_FLOAT))
      fail(where + "@" + name + " must be a numeric scalar");
    T v{};
    a.read(type, &v);
    return v;
  }

  /// Scalar string attribute `name` of `g`, or fail naming it.
  std::string string_attribute(const H5::Group& g, const std::string& where,
                               const std::string& name) const {
    if (!g.attrExists(name)) fail("missing attribute " + where + "@" + name);
    H5::Attribute a = g.openAttribute(name);
    if (a.getSpace().getSimpleExtentNpoints() != 1 || a.getTypeClass() != H5T_STRING)
      fail(where + "@" + name + " must be a string");
    std::string s;
    a.read(a.getStrType(), s);
    return s.c_str();  // drop trailing NULs of fixed-length strings
  }

 private:
  std::string path_;
};

/// A number as a reader would write it: 1e+30, 0.25, NaN (the sign of a NaN means nothing).
inline std::string format_number(double v) {
  if (std::isnan(v)) return "NaN";
  std::ostringstream o;
  o << v;
  return o.str();
}

template <std::size_t K, class T>
std::vector<T> flat(const std::vector<std::array<T, K>>& rows) {
  std::vector<T> out;
  out.reserve(rows.size() * K);
  for (const auto& r : rows) out.insert(out.end(), r.begin(), r.end());
  return out;
}

template <std::size_t K, class T>
std::vector<std::array<T, K>> as_rows(const std::vector<T>& flat) {
  std::vector<std::array<T, K>> out(flat.size() / K);
  for (std::size_t i = 0; i < out.size(); ++i)
    std::copy_n(flat.begin() + static_cast<std::ptrdiff_t>(K * i), K, out[i].begin());
  return out;
}

/// Group names made of digits only ("0001", "000000") are records; anything else is not. A
/// record number beyond what a run can reach (over nine digits) is a damaged file, not a name
/// to skip: `r` fails naming the group.
inline bool parse_counter(const std::string& name, int& value, const Reader& r,
                          const std::string& parent) {
  if (name.empty() || !std::all_of(name.begin(), name.end(),
                                   [](unsigned char c) { return std::isdigit(c) != 0; }))
    return false;
  if (name.size() > 9) r.fail(parent + "/" + name + ": record number out of range");
  value = std::stoi(name);
  return true;
}

}  // namespace crumple::analysis::h5
