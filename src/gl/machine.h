// The line that names the machine a figure was measured on; it goes beside every figure
// (bench, sweep, check's report).
#pragma once

#include <string>

namespace sl {

// "2 cores, llvmpipe (LLVM 15.0.6, 256 bits), GL 4.5 (Core Profile) Mesa 22.3.6" from the current
// GL context and the CPUs this process may use (affinity and cgroup quota: io/box.h).
std::string machineLine();

}  // namespace sl
