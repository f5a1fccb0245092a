#pragma once
// A small binary for the command tests: 400 particles, 8 replicas, t ≤ 2 (a second of DSMC), judged by the level
// kinetic; `tail` follows its [dsmc] table (a [compare] table, say).
#include <string>

namespace granmix::test {

inline std::string toy_binary_scene(const std::string& name, const std::string& tail = "") {
  return "[scene]\nname = \"" + name + R"("
[mixture]
species = [{ mass = 1, diameter = 1, density = 0.05 }, { mass = 4, diameter = 1.3, density = 0.05 }]
[collisions]
restitution = 0.8
[time]
end = 2
points = 4
spacing = "linear"
[observables]
temperatures = true
[theory]
level = "kinetic"
[dsmc]
quick = { particles = 400, replicas = 8 }
)" + tail;
}

}  // namespace granmix::test
