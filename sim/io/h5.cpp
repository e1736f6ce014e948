// HDF5 helpers (h5.hpp).
#include "sim/io/h5.hpp"

#include <algorithm>

namespace crumple::h5 {

namespace {
template <class T>
void write_any(H5::Group& g, const std::string& name, const T* data, std::size_t n,
               std::vector<hsize_t> dims, const H5::PredType& type) {
  if (dims.empty()) dims = {static_cast<hsize_t>(n)};
  H5::DataSpace space(static_cast<int>(dims.size()), dims.data());
  if (exists(g, name)) g.unlink(name);
  H5::DataSet ds = g.createDataSet(name, type, space);
  if (n) ds.write(data, type);
}
template <class T>
std::vector<T> read_any(const H5::Group& g, const std::string& name, std::vector<hsize_t>* dims,
                        const H5::PredType& type) {
  H5::DataSet ds = g.openDataSet(name);
  H5::DataSpace space = ds.getSpace();
  const int rank = space.getSimpleExtentNdims();
  std::vector<hsize_t> d(rank);
  space.getSimpleExtentDims(d.data());
  hsize_t n = 1;
  for (auto x : d) n *= x;
  std::vector<T> out(n);
  if (n) ds.read(out.data(), type);
  if (dims) *dims = d;
  return out;
}
}  // namespace

H5::Group group(H5::Group& parent, const std::string& name) {
  return exists(parent, name) ? parent.openGroup(name) : parent.createGroup(name);
}

void units(H5::Group& g, const std::string& name, const std::string& units) {
  H5::DataSet ds = g.openDataSet(name);
  attr(ds, "units", units);
}

bool exists(const H5::Group& g, const std::string& name) {
  return H5Lexists(g.getId(), name.c_str(), H5P_DEFAULT) > 0;
}

void write(H5::Group& g, const std::string& name, const std::vector<double>& v,
           std::vector<hsize_t> dims) {
  write_any(g, name, v.data(), v.size(), std::move(dims), H5::PredType::NATIVE_DOUBLE);
}
void write(H5::Group& g, const std::string& name, const std::vector<std::int32_t>& v,
           std::vector<hsize_t> dims) {
  write_any(g, name, v.data(), v.size(), std::move(dims), H5::PredType::NATIVE_INT32);
}
void write(H5::Group& g, const std::string& name, const std::vector<std::uint8_t>& v,
           std::vector<hsize_t> dims) {
  write_any(g, name, v.data(), v.size(), std::move(dims), H5::PredType::NATIVE_UINT8);
}
void write(H5::Group& g, const std::string& name, const std::vector<std::int8_t>& v) {
  write_any(g, name, v.data(), v.size(), {}, H5::PredType::NATIVE_INT8);
}

void write_string(H5::Group& g, const std::string& name, const std::string& s) {
  H5::StrType type(H5::PredType::C_S1, H5T_VARIABLE);
  H5::DataSpace space(H5S_SCALAR);
  if (exists(g, name)) g.unlink(name);
  H5::DataSet ds = g.createDataSet(name, type, space);
  ds.write(s, type);
}

void attr(H5::H5Object& o, const std::string& name, const std::string& value) {
  H5::StrType type(H5::PredType::C_S1, H5T_VARIABLE);
  if (o.attrExists(name)) o.removeAttr(name);
  H5::Attribute a = o.createAttribute(name, type, H5::DataSpace(H5S_SCALAR));
  a.write(type, value);
}
void attr(H5::H5Object& o, const std::string& name, double value) {
  if (o.attrExists(name)) o.removeAttr(name);
  H5::Attribute a =
      o.createAttribute(name, H5::PredType::NATIVE_DOUBLE, H5::DataSpace(H5S_SCALAR));
  a.write(H5::PredType::NATIVE_DOUBLE, &value);
}
void attr(H5::H5Object& o, const std::string& name, std::int64_t value) {
  if (o.attrExists(name)) o.removeAttr(name);
  H5::Attribute a = o.createAttribute(name, H5::PredType::NATIVE_INT64, H5::DataSpace(H5S_SCALAR));
  a.write(H5::PredType::NATIVE_INT64, &value);
}

std::vector<double> read_doubles(const H5::Group& g, const std::string& name,
                                 std::vector<hsize_t>* dims) {
  return read_any<double>(g, name, dims, H5::PredType::NATIVE_DOUBLE);
}
std::vector<std::int32_t> read_ints(const H5::Group& g, const std::string& name,
                                    std::vector<hsize_t>* dims) {
  return read_any<std::int32_t>(g, name, dims, H5::PredType::NATIVE_INT32);
}
std::vector<std::uint8_t> read_bytes(const H5::Group& g, const std::string& name) {
  return read_any<std::uint8_t>(g, name, nullptr, H5::PredType::NATIVE_UINT8);
}
std::vector<std::int8_t> read_int8(const H5::Group& g, const std::string& name) {
  return read_any<std::int8_t>(g, name, nullptr, H5::PredType::NATIVE_INT8);
}

std::string read_string(const H5::Group& g, const std::string& name) {
  H5::DataSet ds = g.openDataSet(name);
  H5::StrType type(H5::PredType::C_S1, H5T_VARIABLE);
  std::string s;
  ds.read(s, type);
  return s;
}

std::string attr_string(const H5::H5Object& o, const std::string& name) {
  H5::Attribute a = o.openAttribute(name);
  H5::StrType type(H5::PredType::C_S1, H5T_VARIABLE);
  std::string s;
  a.read(type, s);
  return s;
}
double attr_double(const H5::H5Object& o, const std::string& name) {
  double v;
  o.openAttribute(name).read(H5::PredType::NATIVE_DOUBLE, &v);
  return v;
}
std::int64_t attr_int(const H5::H5Object& o, const std::string& name) {
  std::int64_t v;
  o.openAttribute(name).read(H5::PredType::NATIVE_INT64, &v);
  return v;
}

std::vector<std::string> members(const H5::Group& g) {
  std::vector<std::string> out;
  for (hsize_t i = 0; i < g.getNumObjs(); ++i) out.push_back(g.getObjnameByIdx(i));
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace crumple::h5
