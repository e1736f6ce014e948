// The built-in stage types, registered by name. Adding a stage type: write its file in
// protocols/stages/ with a function returning its StageType, and add one line here.
#include "protocols/registry.hpp"

namespace crumple {
namespace stages {
StageType roll_stage_type();
StageType compress_stage_type();
StageType release_stage_type();
StageType unfold_stage_type();
StageType radial_confine_stage_type();
StageType spherical_stamp_stage_type();
StageType conical_pack_stage_type();
StageType fold_stage_type();
}  // namespace stages

void register_builtin_stages(StageRegistry& r) {
  r.add(stages::roll_stage_type());
  r.add(stages::compress_stage_type());
  r.add(stages::release_stage_type());
  r.add(stages::unfold_stage_type());
  r.add(stages::radial_confine_stage_type());
  r.add(stages::spherical_stamp_stage_type());
  r.add(stages::conical_pack_stage_type());
  r.add(stages::fold_stage_type());
}

}  // namespace crumple
