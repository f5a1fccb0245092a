#include "html_report.hpp"

#include <fmt/format.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <vector>

#include "granmix_version.hpp"
#include "provenance.hpp"
#include "tsv_writer.hpp"

namespace granmix::compare {

namespace {

using nlohmann::ordered_json;

const char* const style = R"(<style>
body { font-family: "DejaVu Sans", Arial, sans-serif; font-size: 14px; margin: 1.5em; color: #222; }
h1 { font-size: 1.5em; margin-bottom: 0.2em; } h2 { font-size: 1.2em; margin: 1.6em 0 0.2em; border-top: 2px solid #ccc; padding-top: 0.8em; }
table.summary { border-collapse: collapse; } table.summary td, table.summary th { border: 1px solid #ccc; padding: 2px 8px; }
table.summary th { background: #eee; } td.num { text-align: right; font-family: monospace; }
.pass { background: #d8f0d8; color: #155a15; font-weight: bold; } .fail { background: #f8d0d0; color: #8a1010; font-weight: bold; }
.verdict { display: inline-block; padding: 2px 10px; border-radius: 3px; }
.scene { display: flex; gap: 1.5em; align-items: flex-start; } .scene img { width: 620px; border: 1px solid #ccc; }
.details { flex: 1; min-width: 360px; } .q { border-left: 4px solid #ccc; padding: 0.2em 0.8em; margin: 0.6em 0; }
.q.ok { border-color: #4a4; } .q.bad { border-color: #c33; } .why { color: #444; } ul.kv { margin: 0.2em 0; padding-left: 1.4em; }
.errors, .warning { background: #f8d0d0; padding: 0.5em 1em; } .source { font-style: italic; } .files a { margin-right: 1em; }
</style>
)";

// The rule of compare/deviations.cpp: the parts add (docs/judging.md).
const char* const rule_text =
    "A judged point passes when |dsmc − theory| ≤ model error · |theory| + z · dsmc_err (or ≤ absolute), where the model error is "
    "the quantity's relative part plus the largest |theory − companion|/|theory| of its correction_from companions plus the "
    "level's own error column, and stays within model_error_max where one is set.";

// A number as the summary table prints it: fixed decimals, or "-" when absent (theory-only scenes).
std::string number(const ordered_json& j, const char* key, const char* format) {
  if (!j.contains(key) || !j[key].is_number()) return "-";
  return fmt::format(fmt::runtime(format), j[key].get<double>());
}

// Any JSON value as HTML: objects as key lists (the tolerance parts, however many the scene declares).
std::string render(const ordered_json& v) {
  if (v.is_string()) return html_escape(v.get<std::string>());
  if (v.is_boolean()) return v.get<bool>() ? "yes" : "no";
  if (v.is_number()) return fmt::format("{:.6g}", v.get<double>());
  if (v.is_array()) {
    std::string s;
    for (const auto& x : v) s += (s.empty() ? "" : ", ") + render(x);
    return s;
  }
  if (v.is_object()) {
    std::string s = "<ul class=\"kv\">";
    for (const auto& [k, x] : v.items()) s += "<li><b>" + html_escape(k) + "</b>: " + render(x) + "</li>";
    return s + "</ul>";
  }
  return "-";
}

// The rule of compare/deviations.cpp in words: "0.0001 + |Δ converged, cooling4| + phi_error + 4σ (or ±0.02), model error ≤ 0.03"
// — the relative part, the computed parts (companions' differences, the level's error column), the statistical part; they add.
std::string tolerance_cell(const ordered_json& t) {
  if (!t.is_object() || !t.contains("relative") || !t.contains("z")) return render(t);
  std::vector<std::string> computed;
  if (t.contains("correction_from")) {
    const ordered_json& c = t["correction_from"];
    if (c.is_string()) computed.push_back(c.get<std::string>());
    if (c.is_array())
      for (const auto& x : c) computed.push_back(x.is_string() ? x.get<std::string>() : x.dump());
  }
  const std::string column = t.contains("error_column") && t["error_column"].is_string() ? t["error_column"].get<std::string>() : "";
  const double relative = t["relative"].get<double>();
  std::string s = (computed.empty() && column.empty()) || relative > 0 ? fmt::format("{:g}", relative) : "";
  if (!computed.empty()) s += fmt::format("{}|Δ {}|", s.empty() ? "" : " + ", fmt::join(computed, ", "));
  if (!column.empty()) s += (s.empty() ? "" : " + ") + column;
  s += fmt::format(" + {:g}σ", t["z"].get<double>());
  if (t.contains("absolute") && t["absolute"].is_number() && t["absolute"].get<double>() > 0)
    s += fmt::format(" (or ±{:g})", t["absolute"].get<double>());
  if (t.contains("model_error_max") && t["model_error_max"].is_number())
    s += fmt::format(", model error ≤ {:g}", t["model_error_max"].get<double>());
  return html_escape(s);
}

std::string verdict(bool pass) { return pass ? "<span class=\"verdict pass\">pass</span>" : "<span class=\"verdict fail\">FAIL</span>"; }

ordered_json read_json(const std::filesystem::path& p) {
  std::ifstream in(p);
  if (!in) throw std::runtime_error("html report: cannot read " + p.string());
  return ordered_json::parse(in);
}

std::string summary_table(const ordered_json& summary) {
  std::string s = "<table class=\"summary\">\n<tr><th>scene</th><th>quantity</th><th>max rel</th><th>max z</th><th>tolerance</th><th>pass</th></tr>\n";
  for (const auto& sc : summary["scenes"]) {
    const std::string name = sc.value("scene", "");
    const std::string link = "<a href=\"#" + html_escape(name) + "\">" + html_escape(name) + "</a>";
    if (!sc.contains("quantities") || sc["quantities"].empty()) {
      s += "<tr><td>" + link + "</td><td>-</td><td class=\"num\">-</td><td class=\"num\">-</td><td>theory only</td><td class=\"" +
           std::string(sc.value("pass", false) ? "pass" : "fail") + "\">" + (sc.value("pass", false) ? "yes" : "NO") + "</td></tr>\n";
      continue;
    }
    for (const auto& [label, q] : sc["quantities"].items()) {
      // "chance": failed at this seed, passed its confirmation (docs/judging.md §2.1)
      const bool chance = q.value("verdict", "") == "chance", pass = q.value("pass", false) || chance;
      s += "<tr><td>" + link + "</td><td>" + html_escape(label) + "</td><td class=\"num\">" + number(q, "max_rel", "{:.4f}") +
           "</td><td class=\"num\">" + number(q, "max_z", "{:.2f}") + "</td><td>" + tolerance_cell(q.value("tolerance", ordered_json())) +
           "</td><td class=\"" + (pass ? "pass" : "fail") + "\">" + (chance ? "chance" : pass ? "yes" : "NO") + "</td></tr>\n";
    }
  }
  return s + "</table>\n";
}

// One judged quantity: its result, tolerance parts (and any further fields of report.json), why.
std::string quantity_block(const std::string& label, const ordered_json& q) {
  const bool pass = q.contains("pass") ? q.value("pass", false) : q.value("failed", 1) == 0 && q.value("judged", 0) > 0;
  std::string s = "<div class=\"q " + std::string(pass ? "ok" : "bad") + "\"><b>" + html_escape(label) + "</b> " + verdict(pass) +
                  fmt::format(" max rel {}, max z {}", number(q, "max_rel", "{:.4f}"), number(q, "max_z", "{:.2f}"));
  if (q.contains("judged"))
    s += fmt::format(", {} of {} points judged, {} failed", q.value("judged", 0), q.value("points", 0), q.value("failed", 0));
  ordered_json parts = ordered_json::object();
  if (q.contains("tolerance")) parts["tolerance"] = q["tolerance"];
  for (const auto& [k, v] : q.items())
    if (k != "max_rel" && k != "max_z" && k != "pass" && k != "points" && k != "judged" && k != "failed" && k != "why" && k != "tolerance")
      parts[k] = v;
  s += render(parts);
  if (q.contains("why")) s += "<p class=\"why\"><b>why:</b> " + render(q["why"]) + "</p>";
  return s + "</div>\n";
}

// A scene's section: its folder `dir`, the links to its files prefixed by `link` (the validation page links into the
// scene folders; the scene's own page sits in its folder).
std::string scene_section(const std::filesystem::path& dir, const std::string& name, bool pass, const std::string& link) {
  const auto href = [&](const std::string& file) { return html_escape(link + file); };
  std::string s = "<h2 id=\"" + html_escape(name) + "\">" + html_escape(name) + " " + verdict(pass) + "</h2>\n";
  if (!std::filesystem::exists(dir / "report.json")) return s + "<p>no report.json in " + html_escape(dir.string()) + "</p>\n";
  const ordered_json rep = read_json(dir / "report.json");
  if (rep.contains("title")) s += "<p><b>" + render(rep["title"]) + "</b></p>\n";
  for (const auto& w : rep.value("warnings", ordered_json::array())) s += "<p class=\"warning\"><b>warning:</b> " + render(w) + "</p>\n";
  s += "<div class=\"scene\">\n";
  if (std::filesystem::exists(dir / (name + ".png")))
    s += "<a href=\"" + href(name + ".png") + "\"><img src=\"" + href(name + ".png") + "\" alt=\"figure of " + html_escape(name) + "\"></a>\n";
  else
    s += "<p>no figure: " + render(rep.value("figure", ordered_json("not drawn"))) + "</p>\n";
  s += "<div class=\"details\">\n<p class=\"source\">Paper: " + render(rep.value("source", ordered_json("-"))) + "</p>\n";
  if (rep.contains("level")) s += "<p>theory level " + render(rep["level"]) + (rep.contains("level_choice") ? ": " + render(rep["level_choice"]) : "") + "</p>\n";
  s += fmt::format("<p>fidelity {}, seed {}, {} particles × {} replicas, theory {} s, DSMC {} s</p>\n",
                   render(rep.value("fidelity", ordered_json("-"))), render(rep.value("seed", ordered_json("-"))),
                   render(rep.value("particles", ordered_json(0))), render(rep.value("replicas", ordered_json(0))),
                   number(rep, "theory_seconds", "{:.3f}"), number(rep, "dsmc_seconds", "{:.2f}"));
  if (rep.contains("quantities"))
    for (const auto& [label, q] : rep["quantities"].items()) s += quantity_block(label, q);
  s += "<p class=\"files\">";
  const std::vector<std::string> files{"theory.tsv", "dsmc.tsv", "distribution.tsv", "deviations.tsv", "report.json", name + ".pdf", name + ".gp"};
  for (const std::string& f : files)
    if (std::filesystem::exists(dir / f)) s += "<a href=\"" + href(f) + "\">" + html_escape(f) + "</a>";
  return s + "</p>\n</div>\n</div>\n";
}

}  // namespace

std::string html_escape(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  for (char c : s) switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  return out;
}

std::string html_report(const std::filesystem::path& out) {
  const ordered_json summary = read_json(out / "summary.json");
  const bool pass = summary.value("pass", false);
  std::size_t quantities = 0, passed = 0;
  for (const auto& sc : summary["scenes"])
    if (sc.contains("quantities"))
      for (const auto& [label, q] : sc["quantities"].items()) ++quantities, passed += q.value("pass", false);
  std::string s = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>granmix validate</title>\n";
  s += style;
  s += "</head>\n<body>\n<h1>granmix validate " + verdict(pass) + "</h1>\n";
  s += fmt::format("<p>{} scenes, {} of {} compared quantities pass, {} scene errors; granmix {} (git {}), written {}. {} "
                   "<a href=\"summary.tsv\">summary.tsv</a> <a href=\"summary.json\">summary.json</a></p>\n",
                   summary["scenes"].size(), passed, quantities, summary.value("errors", ordered_json::array()).size(), granmix::version,
                   granmix::git_sha, utc_now_iso8601(), rule_text);
  if (summary.contains("confirmation") && summary["confirmation"].is_object()) {
    const ordered_json& c = summary["confirmation"];
    s += fmt::format("<p>Confirmation: {} scene(s) that failed on their points' statistics, measured again at seed {} with {}x the "
                     "replicas (<a href=\"confirmation/index.html\">confirmation/</a>); a quantity fails when it fails both times, "
                     "\"chance\" when its confirmation passes.</p>\n",
                     c.value("scenes", ordered_json::array()).size(), c.value("seed", std::uint64_t{0}), c.value("replica_factor", 0));
  }
  if (!summary.value("errors", ordered_json::array()).empty()) {
    s += "<div class=\"errors\"><b>Scenes that did not run:</b><ul>";
    for (const auto& e : summary["errors"]) s += "<li>" + render(e) + "</li>";
    s += "</ul></div>\n";
  }
  s += summary_table(summary);
  for (const auto& sc : summary["scenes"]) {
    const std::string name = sc.value("scene", "");
    s += scene_section(out / name, name, sc.value("pass", false), name + "/");
  }
  return s + "</body>\n</html>\n";
}

void write_html_report(const std::filesystem::path& out) { write_atomically(out / "index.html", html_report(out)); }

std::string scene_html_report(const std::filesystem::path& dir) {
  const ordered_json rep = read_json(dir / "report.json");
  const std::string name = rep.value("scene", dir.filename().string());
  std::string s = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>granmix compare " + html_escape(name) +
                  "</title>\n" + style + "</head>\n<body>\n";
  s += fmt::format("<p>granmix {} (git {}), written {}. {}</p>\n", granmix::version, granmix::git_sha, utc_now_iso8601(), rule_text);
  s += scene_section(dir, name, rep.value("pass", false), "");
  return s + "</body>\n</html>\n";
}

void write_scene_html_report(const std::filesystem::path& dir) { write_atomically(dir / "index.html", scene_html_report(dir)); }

}  // namespace granmix::compare
