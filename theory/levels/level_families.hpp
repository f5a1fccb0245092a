#pragma once
// Each family of levels declares its levels in its own file; the catalogue calls these once (level_catalogue.cpp).
namespace granmix::theory {

class LevelCatalogue;

void declare_paper_levels(LevelCatalogue& c);          // paper_level.cpp
void declare_kinetic_levels(LevelCatalogue& c);        // kinetic_level.cpp
void declare_converged_levels(LevelCatalogue& c);      // converged_level.cpp
void declare_hcs_converged_levels(LevelCatalogue& c);  // hcs_converged_level.cpp

}  // namespace granmix::theory
