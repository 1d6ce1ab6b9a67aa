// The revision of the checkout this binary was built from (git rev-parse --short HEAD, read at every build;
// "unknown" outside a git checkout): recorded in stats, benchmark rows and screenshot sidecars.
#pragma once

namespace raylab {

const char* gitRevision();

}  // namespace raylab
