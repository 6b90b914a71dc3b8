// The five joint studies (private to the studies; run_joint_study dispatches to them).
#pragma once

#include "styk/studies/joints/joint_report.hpp"

namespace styk::studies::joints {

JointReport shrink_fit_study(const ElementRegistry& registry, const JointOptions& options);
JointReport conical_fit_study(const ElementRegistry& registry, const JointOptions& options);
JointReport spline_study(const ElementRegistry& registry, const JointOptions& options);
JointReport p3g_study(const ElementRegistry& registry, const JointOptions& options);
JointReport bolted_flange_study(const ElementRegistry& registry, const JointOptions& options);

}  // namespace styk::studies::joints
