#include "repro/report.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>

#include "cagd/core/csv.hpp"
#include "cagd/core/errors.hpp"
#include "cagd/io/output_file.hpp"
#include "repro/reference.hpp"

namespace cagd::repro {

namespace fs = std::filesystem;

namespace {
struct Row {
    std::map<std::string, std::string> f;
    const std::string& operator[](const std::string& k) const {
        static const std::string empty;
        const auto it = f.find(k);
        return it == f.end() ? empty : it->second;
    }
};

struct Artifact {
    std::string paper, name, title, section, reference, experiment;
    std::vector<std::string> provenance, notes, timings;
    std::vector<std::pair<std::string, std::string>> figures;
    std::vector<Row> rows;
};

const std::vector<std::pair<std::string, std::string>> kPapers = {
    {"pseudo_energy", "Inoue, Shibata, Kanatani — cubic Hermite spline with minimum pseudo-energy"},
    {"sb2_locality", "Kuroda, Furukawa, Kimura — S-splines and B2-splines with controllable locality"},
    {"hosaka", "Hosaka — theory of curve and surface synthesis and smoothing"},
    {"typical_curves", "Miura, Shirahata, Agari — nonstationary typical curves, extension to surfaces"},
    {"curvature_profile",
     "Kuroda, Higashi, Saito, Watanabe — composite interpolants, curvature piecewise 0–2nd degree in arc length"},
};

std::vector<Row> read_checks(const fs::path& p) {
    std::ifstream in(p);
    std::string line;
    std::vector<std::string> header;
    std::vector<Row> rows;
    while (std::getline(in, line)) {
        const auto f = split_csv_line(line);
        if (header.empty()) {
            header = f;
            continue;
        }
        Row r;
        for (std::size_t i = 0; i < header.size() && i < f.size(); ++i) r.f[header[i]] = f[i];
        rows.push_back(r);
    }
    return rows;
}

Artifact read_artifact(const fs::path& meta, const std::string& paper) {
    Artifact a;
    a.paper = paper;
    a.name = meta.stem().string();
    std::ifstream in(meta);
    std::string line;
    while (std::getline(in, line)) {
        const auto colon = line.find(": ");
        if (colon == std::string::npos) continue;
        const std::string k = line.substr(0, colon), v = line.substr(colon + 2);
        if (k == "title")
            a.title = v;
        else if (k == "section")
            a.section = v;
        else if (k == "reference")
            a.reference = v;
        else if (k == "experiment")
            a.experiment = v;
        else if (k == "provenance")
            a.provenance.push_back(v);
        else if (k == "note")
            a.notes.push_back(v);
        else if (k == "timing")
            a.timings.push_back(v);
        else if (k == "figure") {
            const auto bar = v.find('|');
            a.figures.emplace_back(v.substr(0, bar), bar == std::string::npos ? "" : v.substr(bar + 1));
        }
    }
    a.rows = read_checks(meta.parent_path() / (a.name + ".checks.csv"));
    return a;
}

std::string md(const std::string& s) {  // escape table pipes
    std::string o;
    for (char c : s) {
        if (c == '|')
            o += "\\|";
        else
            o += c;
    }
    return o;
}

std::string anchor(const std::string& erratum) {
    std::string a;
    for (char c : erratum) a += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return a;
}
}  // namespace

// The CSV files a figure's gnuplot script reads, in order: its `datadir.'/FILE.csv'` and
// `datadir.'/'.name.'SUFFIX.csv'` references (name = the figure's name), following `load`ed scripts
// other than the shared style.
std::vector<std::string> figure_data_files(const fs::path& root, const fs::path& script, const std::string& name,
                                           int depth = 0) {
    std::ifstream in(root / script);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::vector<std::string> out;
    auto add = [&](const std::string& file) {
        if (file.size() > 4 && file.compare(file.size() - 4, 4, ".csv") == 0 &&
            std::find(out.begin(), out.end(), file) == out.end())
            out.push_back(file);
    };
    for (const auto& [key, prefix] :
         {std::pair<std::string, std::string>{"datadir.'/'.name.'", name}, {"datadir.'/", ""}})
        for (std::size_t at = text.find(key); at != std::string::npos; at = text.find(key, at + 1)) {
            const std::size_t start = at + key.size(), end = text.find('\'', start);
            if (end == std::string::npos) break;
            add(prefix + text.substr(start, end - start));
        }
    const std::string load = "load '";
    for (std::size_t at = text.find(load); depth < 3 && at != std::string::npos; at = text.find(load, at + 1)) {
        const std::size_t start = at + load.size(), end = text.find('\'', start);
        const std::string other = text.substr(start, end - start);
        if (end == std::string::npos || other.find("style.gp") != std::string::npos) continue;
        for (const auto& f : figure_data_files(root, other, name, depth + 1)) add(f);
    }
    return out;
}

namespace {

// "Beyond the papers": the interpolant benchmark of results/benchmark/ (cagd benchmark), when run:
// its leaderboards as the command wrote them, its convergence figures, the peers with their
// identity table (cagd peers) and the scorecard (cagd scorecard).
std::string benchmark_section(const fs::path& results) {
    const fs::path dir = results / "benchmark";
    const fs::path board = dir / "leaderboard.md";
    if (!fs::exists(board)) return "";
    std::ifstream in(board);
    std::ostringstream text;
    text << in.rdbuf();
    // The leaderboard links its neighbours (classic.md, classic_runs.csv) from results/benchmark/;
    // here they are one folder down.
    std::string board_text = text.str();
    for (std::size_t at = 0; (at = board_text.find("](classic", at)) != std::string::npos; at += 2)
        board_text.insert(at + 2, "benchmark/");
    std::ostringstream s;
    s << "\n<a id=\"benchmark\"></a>\n\n## Beyond the papers: the interpolant benchmark\n\n"
         "Not a claim of any paper: every configuration of the registry on points sampled from curves with a known "
         "answer "
         "(`cagd benchmark`, `src/cagd/compare/truth_benchmark.hpp`; docs/benchmark.md). Errors are dimensionless: the "
         "largest "
         "distance to the true curve and the length error divided by the true length, the tangent angle in radians, "
         "the curvature "
         "error times the true length (largest and L2 over arc length). An observed order is the last pair of "
         "successive "
         "sizes' (in parentheses where the pair before it disagrees by more than 0.2: pre-asymptotic). "
         "Data: [`benchmark/truth_runs.csv`](benchmark/truth_runs.csv), "
         "[`benchmark/convergence_orders.csv`](benchmark/convergence_orders.csv); "
         "script: [`scripts/plot/benchmark_fig_convergence.gp`](../scripts/plot/benchmark_fig_convergence.gp).\n"
      << board_text << "\n#### Convergence\n\n";
    for (const char* family :
         {"line", "circle", "ellipse", "epitrochoid", "clothoid", "log-aesthetic", "helix", "trefoil"})
        if (fs::exists(dir / (std::string("convergence_") + family + ".png")))
            s << "![" << family << "](benchmark/convergence_" << family << ".png)\n\n";
    // The peers (cagd peers) and the scorecard (cagd scorecard; make scorecard) as their pages have
    // them, their headings two levels down, their links to their neighbours (the CSVs, the figure)
    // one folder down.
    for (const char* page : {"peers.md", "scorecard.md"}) {
        std::ifstream in_page(dir / page);
        if (!in_page) continue;
        s << "\n";
        for (std::string line; std::getline(in_page, line);) {
            for (const char* neighbour : {"](peer", "](scorecard"})
                for (std::size_t at = 0; (at = line.find(neighbour, at)) != std::string::npos; at += 2)
                    line.insert(at + 2, "benchmark/");
            s << (line.rfind('#', 0) == 0 ? "##" : "") << line << "\n";
        }
    }
    return s.str();
}

}  // namespace

int write_report(const std::string& root) {
    const fs::path results = fs::path(root) / "results";
    int failed = 0;
    // Both files through io/output_file: published whole after every write succeeded, or not at all.
    OutputFile claims_file((results / "claims.csv").string(), "");
    std::ostream& claims = claims_file.stream();
    // origin: paper (a claim the paper prints) or ours (a statement of ours where it prints none; its
    // status is "ours: holds" or "ours: fails", and paper_value holds our stated value).
    claims << "paper,artifact,claim,paper_value,ours,abs_diff,tolerance,status,erratum,ours_range,choices,origin\n";
    std::ostringstream body, summary;
    summary << "| paper | claims | unconditional | reproduced | deviates | depends on a choice | failed | validations "
               "(passed / total) | claims of ours (hold / total) |\n"
               "|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    // The digest: every claim that does not simply reproduce, one line each, grouped by paper.
    std::map<std::string, std::string> erratum_titles;
    for (const Erratum& e : load_errata((fs::path(root) / "reference" / "ERRATA.md").string()))
        erratum_titles[e.id] = e.title;
    std::ostringstream digest;
    int total_n = 0, total_rep = 0, total_dev = 0, total_dep = 0, total_fail = 0, total_val = 0, total_val_ok = 0,
        total_ours = 0, total_ours_ok = 0;
    for (const auto& [paper, title] : kPapers) {
        const fs::path dir = results / paper;
        if (!fs::exists(dir)) {
            summary << "| `" << paper << "` | — | — | — | — | — | — | not yet reproduced | — |\n";
            continue;
        }
        std::vector<Artifact> arts;
        std::vector<fs::path> metas;
        for (const auto& e : fs::directory_iterator(dir))
            if (e.path().extension() == ".meta") metas.push_back(e.path());
        std::sort(metas.begin(), metas.end());
        for (const auto& m : metas) arts.push_back(read_artifact(m, paper));
        std::stable_sort(arts.begin(), arts.end(), [](const Artifact& x, const Artifact& y) {
            return std::make_pair(x.section, x.name) < std::make_pair(y.section, y.name);
        });
        int n = 0, rep = 0, dev = 0, dep = 0, fail = 0, val = 0, val_ok = 0, ours = 0, ours_ok = 0;
        body << "\n<a id=\"" << paper << "\"></a>\n\n## `" << paper << "` — " << title << "\n";
        std::ostringstream paper_digest;
        for (const auto& a : arts) {
            body << "\n### " << a.title << " (`" << a.name << "`)\n\n";
            body << "Paper: " << a.section << ". Reference: [`" << a.reference << "`](../" << a.reference
                 << "). Experiment: [`" << a.experiment << "`](../" << a.experiment << ").\n";
            for (const auto& p : a.provenance) body << "> " << p << "\n";
            if (!a.provenance.empty()) body << "\n";
            for (const auto& note : a.notes) body << "- " << note << "\n";
            const bool has_claims =
                std::any_of(a.rows.begin(), a.rows.end(), [](const Row& r) { return r["kind"] == "claim"; });
            if (has_claims)
                body << "\n| claim | statement | paper | ours | \\|Δ\\| | tolerance | status |\n"
                        "|---|---|---:|---:|---:|---:|---|\n";
            std::ostringstream vals, own;
            for (const auto& r : a.rows) {
                const std::string status = r["status"];
                if (r["kind"] == "ours") {
                    ++ours;
                    ours_ok += status == "ours: holds";
                    claims << csv_field(paper) << "," << csv_field(a.name) << "," << csv_field(r["id"]) << ","
                           << csv_field(r["paper_value"]) << "," << r["ours"] << "," << r["abs_diff"] << ","
                           << r["tolerance"] << "," << status << "," << r["erratum"] << ","
                           << csv_field(r["ours_range"]) << "," << csv_field(r["choices"]) << ",ours\n";
                    own << "| `" << r["id"].substr(paper.size() + 1) << "` | " << md(r["description"]) << " | "
                        << md(r["paper_value"]) << " | " << r["ours"] << " | " << r["abs_diff"] << " | "
                        << r["tolerance"] << " | " << (status == "ours: holds" ? "holds" : "**fails**") << " |\n";
                    failed += status != "ours: holds";
                    continue;
                }
                if (r["kind"] == "claim") {
                    ++n;
                    rep += status == "reproduced";
                    dev += status == "deviates";
                    dep += status == "depends";
                    fail += status == "failed";
                    claims << csv_field(paper) << "," << csv_field(a.name) << "," << csv_field(r["id"]) << ","
                           << csv_field(r["paper_value"]) << "," << r["ours"] << "," << r["abs_diff"] << ","
                           << r["tolerance"] << "," << status << "," << r["erratum"] << ","
                           << csv_field(r["ours_range"]) << "," << csv_field(r["choices"]) << ",paper\n";
                    std::string shown = status == "failed"    ? "**failed**"
                                        : status == "depends" ? "**depends**"
                                                              : status;
                    if (!r["erratum"].empty())
                        shown += " ([" + r["erratum"] + "](../reference/ERRATA.md#" + anchor(r["erratum"]) + "))";
                    // Checked over the choices the paper leaves open: the range, and which choices decide.
                    if (!r["choices"].empty())
                        shown += std::string(status == "depends" ? " — ours ∈ " : " — unconditional: ours ∈ ") +
                                 r["ours_range"] + " over " + md(r["choices"]);
                    body << "| `" << r["id"].substr(paper.size() + 1) << "` | " << md(r["description"]) << " | "
                         << md(r["paper_value"]) << " | " << r["ours"] << " | " << r["abs_diff"] << " | "
                         << r["tolerance"] << " | " << shown << " |\n";
                    if (status != "reproduced") {
                        paper_digest << "- `" << r["id"].substr(paper.size() + 1) << "` (" << a.name << "): printed "
                                     << md(r["paper_value"]) << ", ours " << r["ours"] << " — "
                                     << (status == "deviates" ? "deviates" : "**" + status + "**");
                        if (!r["erratum"].empty()) {
                            const auto t = erratum_titles.find(r["erratum"]);
                            paper_digest << ", [" << r["erratum"] << "](../reference/ERRATA.md#" << anchor(r["erratum"])
                                         << ")";
                            if (t != erratum_titles.end() && !t->second.empty()) paper_digest << ": " << md(t->second);
                        }
                        paper_digest << "\n";
                    }
                } else {
                    ++val;
                    val_ok += status == "reproduced";
                    vals << "| `" << r["id"].substr(paper.size() + 1) << "` | " << md(r["description"]) << " | "
                         << r["paper_value"] << " | " << r["ours"] << " | " << r["abs_diff"] << " | " << r["tolerance"]
                         << " (" << md(r["tolerance_reason"]) << ") | "
                         << (status == "reproduced" ? "passed" : "**failed**") << " |\n";
                }
                failed += status == "failed";
            }
            if (!own.str().empty())
                body << "\nClaims of ours — statements we make where the paper prints no number, counted apart from "
                        "the paper's (the statement says "
                        "whether it was written before or after a first measurement):\n\n"
                        "| claim | statement | stated value | ours | \\|Δ\\| | tolerance | verdict |\n"
                        "|---|---|---:|---:|---:|---:|---|\n"
                     << own.str();
            if (!vals.str().empty())
                body << "\nValidation — library value against an independent recomputation:\n\n"
                        "| check | what | reference | library | \\|Δ\\| | tolerance | result |\n"
                        "|---|---|---:|---:|---:|---|---|\n"
                     << vals.str();
            if (!a.timings.empty()) {
                body << "\nTiming claims — measured in every run, never pass/fail, not byte-stable: the measured "
                        "ratios are in "
                        "`results/timing/"
                     << paper << "_" << a.name
                     << ".csv` (not committed).\n\n"
                        "| claim | statement | paper ratio | interval the printed digits allow |\n|---|---|---:|---|\n";
                for (const auto& t : a.timings) {
                    std::vector<std::string> f;
                    std::stringstream ss(t);
                    std::string x;
                    while (std::getline(ss, x, '|')) f.push_back(x);
                    if (f.size() == 5)
                        body << "| `" << f[0].substr(paper.size() + 1) << "` | " << md(f[1]) << " | " << f[2] << " | ["
                             << f[3] << ", " << f[4] << "] |\n";
                }
            }
            for (const auto& [name, caption] : a.figures) {
                const std::string script = "scripts/plot/" + paper + "_" + name + ".gp";
                body << "\n![" << md(caption) << "](" << paper << "/" << name << ".png)\n\n*" << caption << "* — data:";
                const std::vector<std::string> files = figure_data_files(fs::path(root), script, name);
                for (std::size_t i = 0; i < files.size(); ++i)
                    body << (i ? ", " : " ") << "[`" << paper << "/" << files[i] << "`](" << paper << "/" << files[i]
                         << ")";
                if (files.empty()) body << " (none read by the script)";
                body << "; script: [`" << script << "`](../" << script << ")\n";
            }
        }
        if (!paper_digest.str().empty())
            digest << "\n**[`" << paper << "`](#" << paper << ")** — " << dev + dep + fail << " of " << n
                   << " claims:\n\n"
                   << paper_digest.str();
        summary << "| [`" << paper << "`](#" << paper << ") | " << n << " | " << rep + dev << " | " << rep << " | "
                << dev << " | " << dep << " | " << fail << " | " << val_ok << " / " << val << " | " << ours_ok << " / "
                << ours << " |\n";
        total_n += n, total_rep += rep, total_dev += dev, total_dep += dep, total_fail += fail, total_val += val,
            total_val_ok += val_ok, total_ours += ours, total_ours_ok += ours_ok;
    }
    summary << "| **all** | " << total_n << " | " << total_rep + total_dev << " | " << total_rep << " | " << total_dev
            << " | " << total_dep << " | " << total_fail << " | " << total_val_ok << " / " << total_val << " | "
            << total_ours_ok << " / " << total_ours << " |\n";
    OutputFile report_file((results / "REPORT.md").string(), "");
    std::ostream& report = report_file.stream();
    report << "# cagd-repro — reproduction report\n\n"
              "Generated by `make reproduce` (src/repro/report.cpp); do not edit. Every value in the\n"
              "*ours* column is computed by the library at run time. Status: **reproduced** = within the\n"
              "tolerance of the paper's printed value; **deviates** = outside it, with an erratum in\n"
              "[reference/ERRATA.md](../reference/ERRATA.md) that shows why, and the corrected statement\n"
              "checked; **depends** = the verdict changes with a choice the paper leaves open (a free\n"
              "constant, a fit range, a threshold, a reading of the text): the row gives the range of\n"
              "*ours* over the choices we tried and which of them reproduce the paper, *ours* itself being\n"
              "our stated choice; **failed** = outside tolerance with no explanation. *Unconditional* counts\n"
              "the reproduced and deviating claims, whose verdict holds under every choice tried (rows checked\n"
              "over choices say so). Tolerances and their reasons are in the reference files. The\n"
              "machine-readable form is [claims.csv](claims.csv).\n\n"
              "The rule for **depends** (docs/reproduction.md): a claim depends on a choice only when every\n"
              "alternative is one the paper's text allows, our stated choice was fixed before the comparison,\n"
              "and the verdict differs among them. A threshold decides only when the claim's reference row\n"
              "declares it before the run (column `thresholds`). An alternative that exists only to reach the\n"
              "printed number (a stop tuned within a tie, a minimiser assumed to stop in another basin, a\n"
              "threshold added after a measurement, a reading that gives one printed value of a figure and\n"
              "misses its sibling) is a *note*: listed beside the claim, never deciding its status.\n\n"
              "*Claims of ours* are statements we make where the paper prints no number; they hold or fail,\n"
              "are counted apart from the paper's claims (last column; `origin` = ours in claims.csv), and say\n"
              "whether they were written before or after a first measurement.\n\n"
              "## Summary\n\n"
           << summary.str()
           << "\n## Which published results do not hold\n\n"
              "Every claim that is not reproduced, one line each: the paper's printed value, ours, the status and the "
              "erratum\n"
              "that shows why (what is wrong, in its heading's words). The tables below give each claim's tolerance "
              "and source.\n"
           << digest.str() << body.str() << benchmark_section(results);
    claims_file.commit();
    report_file.commit();
    return failed;
}

}  // namespace cagd::repro
