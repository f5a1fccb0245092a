// libFuzzer harness: scene text -> Scene or a clear InputError (model/scene.cpp, theory::load_scene_text: checked against the level catalogue). Any other outcome
// (crash, other exception, sanitizer report, > 2 s) is a finding.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "model/errors.hpp"
#include "model/scene.hpp"
#include "theory/scene_theory.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const granmix::model::Scene s = granmix::theory::load_scene_text(text, "fuzz.toml");
    if (s.theory.sweep) (void)granmix::model::sweep_point(s, s.theory.sweep->values.front());
  } catch (const granmix::InputError&) {      // exit 2 with file:line: key: message
  } catch (const std::invalid_argument&) {    // a model constructor refused a value: exit 2 too (main.cpp)
  }
  return 0;
}
