// A thin layer over the HDF5 C++ API: write and read whole datasets and attributes by name.
// (There is no HighFive on Debian 12; this is all the project needs.) Errors from HDF5 become
// InputError naming the file and the object.
#pragma once

#include <H5Cpp.h>

#include <cstdint>
#include <string>
#include <vector>

namespace crumple::h5 {

/// Opens (or creates) the group at `path` below `parent`.
H5::Group group(H5::Group& parent, const std::string& name);

void write(H5::Group& g, const std::string& name, const std::vector<double>& v,
           std::vector<hsize_t> dims = {});
void write(H5::Group& g, const std::string& name, const std::vector<std::int32_t>& v,
           std::vector<hsize_t> dims = {});
void write(H5::Group& g, const std::string& name, const std::vector<std::uint8_t>& v,
           std::vector<hsize_t> dims = {});
void write(H5::Group& g, const std::string& name, const std::vector<std::int8_t>& v);
void write_string(H5::Group& g, const std::string& name, const std::string& s);

void attr(H5::H5Object& o, const std::string& name, const std::string& value);
void attr(H5::H5Object& o, const std::string& name, double value);
void attr(H5::H5Object& o, const std::string& name, std::int64_t value);

/// The `units` attribute of the dataset `name` of `g` (docs/FILE_FORMAT.md: every dataset has
/// one; "1" for pure numbers, counts, indices and flags, "none" for text).
void units(H5::Group& g, const std::string& name, const std::string& units);

bool exists(const H5::Group& g, const std::string& name);
std::vector<double> read_doubles(const H5::Group& g, const std::string& name,
                                 std::vector<hsize_t>* dims = nullptr);
std::vector<std::int32_t> read_ints(const H5::Group& g, const std::string& name,
                                    std::vector<hsize_t>* dims = nullptr);
std::vector<std::uint8_t> read_bytes(const H5::Group& g, const std::string& name);
std::vector<std::int8_t> read_int8(const H5::Group& g, const std::string& name);
std::string read_string(const H5::Group& g, const std::string& name);
std::string attr_string(const H5::H5Object& o, const std::string& name);
double attr_double(const H5::H5Object& o, const std::string& name);
std::int64_t attr_int(const H5::H5Object& o, const std::string& name);
/// Names of the members of a group, sorted.
std::vector<std::string> members(const H5::Group& g);

}  // namespace crumple::h5
