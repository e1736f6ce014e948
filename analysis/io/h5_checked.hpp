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

template <std::size_t K, class T>
std::vector<std::array<T, K>> as_rows(const std::vector<T>& flat) {
  std::vector<std::array<T, K>> out(flat.size() / K);
  for (std::size_t i = 0; i < out.size(); ++i)
    std::copy_n(flat.begin() + static_cast<std::ptrdiff_t>(K * i), K, out[i].begin());
  return out;
}

/// Group names made of digits only ("0001", "000000"); anything else is not a record.
inline bool parse_counter(const std::string& name, int& value) {
  if (name.empty() || name.size() > 9 || !std::all_of(name.begin(), name.end(), ::isdigit))
    return false;
  value = std::stoi(name);
  return true;
}

}  // namespace crumple::analysis::h5
