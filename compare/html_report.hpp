#pragma once
// out/index.html of a validation run (and a scene's own page, DIR/<scene>/index.html): the summary table (the rows of summary.tsv), then per
// scene its title and paper source, its figure beside every judged quantity's tolerance and `why`,
// and links to its files. Static HTML with inline CSS, no JavaScript. It is built from what the run
// wrote (summary.json and each scene's report.json), so it shows exactly what those files say and
// renders any tolerance fields they carry.
#include <filesystem>
#include <string>
#include <string_view>

namespace granmix::compare {

// &, <, >, " and ' as character references.
std::string html_escape(std::string_view s);

// The page for the validation run written to `out` (summary.json must exist).
std::string html_report(const std::filesystem::path& out);

// out/index.html, written atomically.
void write_html_report(const std::filesystem::path& out);

// DIR/<scene>/index.html of `granmix compare` (and of each scene a validation run writes): the scene's section alone,
// from its report.json, its links relative to the folder.
std::string scene_html_report(const std::filesystem::path& scene_dir);
void write_scene_html_report(const std::filesystem::path& scene_dir);

}  // namespace granmix::compare
