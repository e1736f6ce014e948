// Output path checks (output_paths.hpp).
#include "sim/apps/output_paths.hpp"

#include "sim/core/errors.hpp"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <unistd.h>

namespace crumple {

namespace {
namespace fs = std::filesystem;

// Absent or a regular file; anything else (a directory, a device such as /dev/null, a pipe)
// would be replaced or fail only when the run ends.
void regular_or_absent(const std::string& run, const std::string& path, const std::string& what) {
  std::error_code ec;
  const auto st = fs::symlink_status(path, ec);
  if (!fs::exists(st)) return;
  if (fs::is_directory(st)) throw InputError("-o " + run + ": " + what + " is a directory");
  if (fs::is_symlink(st)) {
    if (fs::is_regular_file(fs::status(path, ec))) return;
    throw InputError("-o " + run + ": " + what + " is a link to something not a regular file");
  }
  if (!fs::is_regular_file(st))
    throw InputError("-o " + run + ": " + what +
                     " is not a regular file (a device, pipe or socket); give a path for a new file");
}

// The directory must exist and take a new file: tried with a probe file, since permission bits
// do not tell a read-only mount (or, for root, anything).
void writable_directory(const std::string& run) {
  const fs::path dir = fs::path(run).parent_path().empty() ? fs::path(".") : fs::path(run).parent_path();
  std::error_code ec;
  if (!fs::exists(dir, ec))
    throw InputError("-o " + run + ": directory " + dir.string() + " does not exist");
  if (!fs::is_directory(dir, ec))
    throw InputError("-o " + run + ": " + dir.string() + " is not a directory");
  const std::string probe = run + ".tmp.new";  // the name checkpoints are written under
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (fd < 0)
    throw InputError("-o " + run + ": cannot create files in " + dir.string() + " (" +
                     std::strerror(errno) + ")");
  ::close(fd);
  ::unlink(probe.c_str());
}
}  // namespace

OutputPaths check_output_paths(const std::string& run, bool xdmf, bool resume, bool force,
                               bool extend) {
  OutputPaths out;
  out.run = run;
  out.tmp = run + ".tmp";
  if (xdmf) {
    out.xdmf = fs::path(run).replace_extension(".xdmf").string();
    out.xdmf_cycles = fs::path(run).replace_extension(".cycles.xdmf").string();
  }
  if (xdmf && fs::path(out.xdmf).lexically_normal() == fs::path(run).lexically_normal())
    throw InputError("-o " + run +
                     ": the XDMF sidecar would overwrite the run file; name the run file .h5 "
                     "(or set output.xdmf: false)");
  regular_or_absent(run, out.run, "the run file");
  regular_or_absent(run, out.tmp, "the checkpoint " + out.tmp);
  if (xdmf) {
    regular_or_absent(run, out.xdmf, "the XDMF sidecar " + out.xdmf);
    regular_or_absent(run, out.xdmf_cycles, "the XDMF sidecar " + out.xdmf_cycles);
  }
  writable_directory(run);
  std::error_code ec;
  // A pending checkpoint continued with --resume replaces the run file at its end, as the run
  // that wrote it (started with --force or --extend while the file was there) was to.
  const bool replaces = force || extend || (resume && fs::exists(out.tmp, ec));
  if (!replaces && fs::exists(out.run, ec))
    throw InputError("-o " + run + ": exists; pass --force to replace it");
  for (const std::string& sidecar : {out.xdmf, out.xdmf_cycles})
    if (!replaces && xdmf && fs::exists(sidecar, ec))
      throw InputError("-o " + run + ": the XDMF sidecar " + sidecar +
                       " exists; pass --force to replace it");
  if (!force && !resume && fs::exists(out.tmp, ec))
    throw InputError(out.tmp +
                     ": holds the checkpoint of an unfinished run; pass --resume to continue it "
                     "or --force to start afresh and discard it");
  return out;
}

}  // namespace crumple
