// What `crumple-sim --resume` accepts (README.md, "Checkpoints and resume"): the checkpoint must
// fit the run's mesh and protocol, and the configuration given on the command line must be the
// run's own except for the keys that steer the numerics or the output without changing the
// problem (the keys the schema marks may_change_on_resume: resumable_keys(), config_schema.hpp).
// Those are applied from the checkpoint on and recorded in /resumes.
#pragma once

#include "protocols/checkpoint.hpp"
#include "sim/io/params.hpp"
#include "sim/io/run_file.hpp"

#include <string>
#include <vector>

namespace crumple {

/// The keys whose values differ between `stored` (the run's configuration) and `given` (the
/// command line's), as "key: OLD -> NEW", if all of them are resumable; otherwise an InputError
/// naming `tmp`, where each offending new value was set, and both values.
std::vector<std::string> resume_changes(const Params& stored, const Params& given,
                                        const std::string& tmp);

/// The keys of `given` that `stored_text` (a run file's /config as stored) lacks: the program
/// gained them after the run started, and they take their given value from the checkpoint on,
/// as "key: (absent: ...) -> NEW".
std::vector<std::string> keys_added_since(const std::string& stored_text, const Params& given);

/// The stored checkpoint, checked against the protocol of `p` (cycle and stage in range) and
/// its integrator history against the mesh (vector lengths); InputError naming `tmp` and the
/// entry at fault.
Checkpoint checkpoint_to_resume(const RunRecord& rec, const Params& p, const std::string& tmp);

}  // namespace crumple
