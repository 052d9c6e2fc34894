#pragma once
// One `rigdesign export` per rig and option set for the whole test run. ctest runs every test
// case in a process of its own, and several cases read the same bundled rig's export (nav2's
// declared keys, one name everywhere, the bridge, the collision monitor): the first process
// to ask writes it under a lock, the others read it. Tests must not change the folder.
#include <string>
#include <vector>

namespace rigdesign::test {

/// The folder `rigdesign export source_path(rig) --to FOLDER args...` wrote (exit code 0, or
/// the test fails there). Kept under the build tree, keyed by the test binary's build, so a
/// rebuilt program never reads an older program's export.
std::string shared_export(const std::string& rig, const std::vector<std::string>& args);

}  // namespace rigdesign::test
