#include "repro/artifact_run.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "cagd/core/errors.hpp"
#include "cagd/io/file_lock.hpp"
#include "cagd/io/output_file.hpp"
#include "cagd/numeric/dense_blocking.hpp"

#ifndef CAGD_SOURCE_DIR
#define CAGD_SOURCE_DIR "."
#endif

namespace cagd::repro {

namespace fs = std::filesystem;

const char* to_string(ClaimStatus s) {
    switch (s) {
        case ClaimStatus::reproduced: return "reproduced";
        case ClaimStatus::deviates: return "deviates";
        case ClaimStatus::depends: return "depends";
        case ClaimStatus::failed: return "failed";
        case ClaimStatus::holds: return "ours: holds";
        case ClaimStatus::fails: return "ours: fails";
    }
    return "failed";
}

ClaimStatus classify(const ReferenceRow& row, double ours, std::optional<double> ours_corrected,
                     bool erratum_documented) {
    if (!std::isfinite(ours)) return ClaimStatus::failed;
    if (std::abs(ours - row.paper_value) <= row.tolerance) return ClaimStatus::reproduced;
    if (row.erratum.empty() || !erratum_documented) return ClaimStatus::failed;
    if (row.corrected_value)
        return std::abs(ours - *row.corrected_value) <= row.tolerance ? ClaimStatus::deviates : ClaimStatus::failed;
    if (ours_corrected && std::abs(*ours_corrected - row.paper_value) <= row.tolerance) return ClaimStatus::deviates;
    return ClaimStatus::failed;
}

MatchOdds match_odds(const std::vector<ChoiceValue>& choices, double printed) {
    MatchOdds odds;
    std::set<long> values;
    for (const ChoiceValue& c : choices) {
        if (c.kind != ChoiceKind::reading) continue;
        if (!(std::abs(c.ours) < 1e15) || c.ours != std::round(c.ours))
            fail_input("repro::match_odds",
                       "reading \"" + c.label + "\" has the value " + full_precision(c.ours) + ", not an integer");
        ++odds.readings;
        odds.matching += c.ours == printed ? 1 : 0;
        values.insert(static_cast<long>(c.ours));
    }
    if (values.empty()) fail_input("repro::match_odds", "needs at least one reading, got none");
    odds.distinct = static_cast<int>(values.size());
    odds.lowest = *values.begin(), odds.highest = *values.rbegin();
    odds.chance = static_cast<double>(odds.distinct) / static_cast<double>(odds.highest - odds.lowest + 1);
    return odds;
}

ClaimStatus classify_over_choices(ClaimStatus stated, const std::vector<bool>& within) {
    if (stated == ClaimStatus::failed || within.empty()) return stated;
    for (bool w : within)
        if (w != within.front()) return ClaimStatus::depends;
    return stated;
}

ArtifactRun::ArtifactRun(std::string paper, std::string artifact, std::string section, std::string title, int argc,
                         char** argv)
    : paper_(std::move(paper)),
      artifact_(std::move(artifact)),
      section_(std::move(section)),
      title_(std::move(title)),
      root_(CAGD_SOURCE_DIR) {
    cagd::numeric::pin_dense_blocking();  // results/ the same on every machine (numeric/dense_blocking.hpp)
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--check")
            check_mode_ = true;
        else if (a == "--root" && i + 1 < argc)
            root_ = argv[++i];
        else
            fail_input("experiment " + paper_ + "/" + artifact_,
                       "unknown argument '" + a + "' (allowed: --check, --root DIR)");
    }
    reference_ = load_reference(root_ + "/reference/" + paper_ + "/" + artifact_ + ".csv");
    for (const auto& id : load_erratum_ids(root_ + "/reference/ERRATA.md")) errata_.insert(id);
    if (check_mode_) {
        std::string pattern =
            (fs::temp_directory_path() / ("cagd-check-" + paper_ + "-" + artifact_ + "-XXXXXX")).string();
        if (mkdtemp(pattern.data()) == nullptr)
            fail_input("experiment " + paper_ + "/" + artifact_,
                       "cannot create a temporary directory '" + pattern + "'");
        out_dir_ = pattern;
    } else {
        out_dir_ = root_ + "/results/" + paper_;
        fs::create_directories(out_dir_);
    }
    // A table cache that exists but is not used (damaged, stale) is rebuilt with one line saying so.
    set_cache_rebuild_notice([](const std::string& path, const std::string& reason) {
        std::cerr << "cagd-repro: cache '" << path << "' not used (" << one_line(reason) << "); rebuilding it\n";
    });
}

ArtifactRun::~ArtifactRun() {
    if (!check_mode_) return;
    std::error_code ignored;  // a destructor does not throw; a directory left in $TMPDIR is harmless
    fs::remove_all(out_dir_, ignored);
}

void ArtifactRun::check(const std::string& short_id, double ours) {
    const ReferenceRow& row = reference_.row(paper_ + "." + short_id);
    const bool documented = !row.erratum.empty() && errata_.count(row.erratum) > 0;
    if (row.ours) {  // a claim of ours: holds within its tolerance, or fails (no erratum can explain it)
        const bool holds = std::isfinite(ours) && std::abs(ours - row.paper_value) <= row.tolerance;
        records_.push_back({"ours", row.id, row.description + " (stated " + row.stated + " a first measurement)",
                            row.paper_value, ours, row.tolerance, row.paper_text, row.tolerance_reason, row.erratum,
                            holds ? ClaimStatus::holds : ClaimStatus::fails});
        return;
    }
    records_.push_back({"claim", row.id, row.description, row.paper_value, ours, row.tolerance, row.paper_text,
                        row.tolerance_reason, row.erratum, classify(row, ours, std::nullopt, documented)});
}

void ArtifactRun::check(const std::string& short_id, double ours, double ours_corrected) {
    check(short_id, ours);
    const ReferenceRow& row = reference_.row(paper_ + "." + short_id);
    if (row.ours)
        fail_input("ArtifactRun::check", row.id + ": a claim of ours has no corrected form (it holds or fails)");
    const bool documented = !row.erratum.empty() && errata_.count(row.erratum) > 0;
    records_.back().status = classify(row, ours, ours_corrected, documented);
}

void ArtifactRun::check_over_choices(const std::string& short_id, double ours, const std::string& stated,
                                     const std::vector<ChoiceValue>& others) {
    check(short_id, ours);
    CheckRecord& r = records_.back();
    const ReferenceRow& row = reference_.row(paper_ + "." + short_id);
    std::vector<ChoiceValue> all{{stated + " (stated)", ours, std::nullopt, ChoiceKind::reading}};
    all.insert(all.end(), others.begin(), others.end());
    std::vector<bool> within;
    double lo = ours, hi = ours;
    // Group the readings by verdict, naming the first few of each group (the stated one first), and
    // the notes likewise; the experiment's own dependence table lists them all.
    constexpr int kNamed = 4;
    std::string text[2][2];  // [note][within]
    int count[2][2] = {{0, 0}, {0, 0}};
    std::string undeclared;
    for (const ChoiceValue& c : all) {
        const bool note = c.kind == ChoiceKind::note;
        if (c.tolerance && !note) {
            const auto& declared = row.thresholds;
            if (std::find(declared.begin(), declared.end(), *c.tolerance) == declared.end())
                undeclared += (undeclared.empty() ? "" : ", ") + format_number(*c.tolerance, 6);
        }
        const bool w = std::isfinite(c.ours) && std::abs(c.ours - r.paper) <= c.tolerance.value_or(r.tolerance);
        if (!note) {
            within.push_back(w);
            lo = std::min(lo, c.ours);
            hi = std::max(hi, c.ours);
        }
        if (count[note][w]++ < kNamed)
            text[note][w] += (text[note][w].empty() ? "" : "; ") + c.label +
                             (c.tolerance ? " (tolerance " + format_number(*c.tolerance, 3) + ")" : "") + ": " +
                             format_number(c.ours, 6);
    }
    r.status = classify_over_choices(r.status, within);
    r.ours_range = "[" + format_number(lo, 6) + ", " + format_number(hi, 6) + "]";
    const auto group = [&](int note, int w) {
        const std::string more =
            count[note][w] > kNamed ? "; " + std::to_string(count[note][w] - kNamed) + " more" : "";
        return std::to_string(count[note][w]) + (count[note][w] ? " (" + text[note][w] + more + ")" : "");
    };
    r.choices = std::to_string(within.size()) + (within.size() == 1 ? " choice" : " choices") +
                "; within tolerance of the paper at " + group(0, 1) + "; outside it at " + group(0, 0);
    if (count[1][0] + count[1][1] > 0)
        r.choices +=
            ". Notes, not readings of the text (never deciding): " + std::to_string(count[1][0] + count[1][1]) +
            "; within tolerance at " + group(1, 1) + "; outside it at " + group(1, 0);
    if (!undeclared.empty()) {  // a threshold the reference row does not declare cannot decide a verdict
        r.status = ClaimStatus::failed;
        r.choices += ". FAILED: threshold(s) " + undeclared + " not declared in the reference row's `thresholds`";
    }
}

void ArtifactRun::check_threshold(const std::string& short_id, double measure, const std::string& what) {
    const ReferenceRow& row = reference_.row(paper_ + "." + short_id);
    if (row.thresholds.empty())
        fail_input("ArtifactRun::check_threshold", row.id + ": the reference row declares no `thresholds`");
    const auto holds = [&](double t) { return std::isfinite(measure) && measure < t ? 1.0 : 0.0; };
    std::vector<ChoiceValue> others;
    for (std::size_t k = 1; k < row.thresholds.size(); ++k)
        others.push_back({what + " < " + format_number(row.thresholds[k], 4), holds(row.thresholds[k])});
    for (const double t : row.note_thresholds)
        others.push_back({what + " < " + format_number(t, 4), holds(t), std::nullopt, ChoiceKind::note});
    check_over_choices(
        short_id, holds(row.thresholds[0]),
        what + " < " + format_number(row.thresholds[0], 4) + " (measured " + format_number(measure, 4) + ")", others);
}

void ArtifactRun::validate(const std::string& short_id, const std::string& description, double fast,
                           double reference_value, double tolerance, const std::string& reason) {
    CheckRecord r{"validation",
                  paper_ + "." + short_id,
                  description,
                  reference_value,
                  fast,
                  tolerance,
                  format_number(reference_value),
                  reason,
                  "",
                  ClaimStatus::failed};
    if (std::isfinite(fast) && std::abs(fast - reference_value) <= tolerance) r.status = ClaimStatus::reproduced;
    records_.push_back(r);
}

void ArtifactRun::figure(const std::string& name, const std::string& caption) { figures_.emplace_back(name, caption); }

void ArtifactRun::note(const std::string& text) { notes_.push_back(text); }

std::string ArtifactRun::cache_path(const std::string& file_name) const {
    const fs::path dir = fs::path(root_) / "build" / "cache" / paper_;
    fs::create_directories(dir);
    return (dir / file_name).string();
}

std::string ArtifactRun::reference_path(const std::string& file_name) const {
    return root_ + "/reference/" + paper_ + "/" + file_name;
}

std::string ArtifactRun::data_path(const std::string& file_name) const { return out_dir_ + "/" + file_name; }

CsvWriter ArtifactRun::table(const std::string& file_name, const std::vector<std::string>& header) const {
    return CsvWriter(data_path(file_name), header);
}

void ArtifactRun::timing(const std::string& short_id, const std::string& description,
                         const std::vector<std::string>& rows_used, double paper_ratio, double lo, double hi,
                         double ours) {
    for (const auto& r : rows_used) {
        reference_.row(paper_ + "." + r);  // throws if the row does not exist
        timing_rows_.insert(paper_ + "." + r);
    }
    timings_.push_back({paper_ + "." + short_id, description, paper_ratio, lo, hi, ours});
}

int ArtifactRun::finish() {
    // A claim of the reference file that was never checked is a failure, never a silent skip.
    for (const auto& row : reference_.rows) {
        bool seen = timing_rows_.count(row.id) > 0;
        for (const auto& r : records_) seen = seen || ((r.kind == "claim" || r.kind == "ours") && r.id == row.id);
        if (!seen)
            records_.push_back({row.ours ? "ours" : "claim", row.id,
                                row.description + " (NOT COMPUTED by the experiment)", row.paper_value, std::nan(""),
                                row.tolerance, row.paper_text, row.tolerance_reason, row.erratum,
                                row.ours ? ClaimStatus::fails : ClaimStatus::failed});
    }
    {
        CsvWriter w(data_path(artifact_ + ".checks.csv"),
                    {"kind", "id", "paper_value", "ours", "abs_diff", "tolerance", "status", "erratum", "description",
                     "tolerance_reason", "ours_range", "choices"});
        for (const auto& r : records_)
            w.row_text({r.kind, r.id, r.paper_text, format_number(r.ours), format_number(std::abs(r.ours - r.paper), 3),
                        format_number(r.tolerance, 3), to_string(r.status), r.erratum, r.description,
                        r.tolerance_reason, r.ours_range, r.choices});
    }
    {
        OutputFile meta_file(data_path(artifact_ + ".meta"), "");  // published whole, or the old file kept
        std::ostream& meta = meta_file.stream();
        meta << "title: " << title_ << "\nsection: " << section_ << "\nreference: reference/" << paper_ << "/"
             << artifact_ << ".csv\nexperiment: experiments/" << paper_ << "/" << artifact_ << ".cpp\n";
        for (const auto& line : reference_.provenance) meta << "provenance: " << line << "\n";
        for (const auto& [name, caption] : figures_) meta << "figure: " << name << "|" << caption << "\n";
        for (const auto& n : notes_) meta << "note: " << n << "\n";
        for (const auto& t : timings_)
            meta << "timing: " << t.id << "|" << t.description << "|" << format_number(t.paper, 4) << "|"
                 << format_number(t.lo, 4) << "|" << format_number(t.hi, 4) << "\n";
        meta_file.commit();
    }
    if (!timings_.empty()) {
        const std::string dir = check_mode_ ? out_dir_ : root_ + "/results/timing";
        std::filesystem::create_directories(dir);
        CsvWriter w(dir + "/" + paper_ + "_" + artifact_ + ".csv",
                    {"id", "description", "paper_ratio", "interval_lo", "interval_hi", "ours", "within"});
        for (const auto& t : timings_)
            w.row_text({t.id, t.description, format_number(t.paper, 4), format_number(t.lo, 4), format_number(t.hi, 4),
                        format_number(t.ours, 4), t.ours >= t.lo && t.ours <= t.hi ? "yes" : "no"});
        for (const auto& t : timings_)
            std::cout << "timing " << t.id << ": ours " << format_number(t.ours, 4) << ", paper "
                      << format_number(t.paper, 4) << " in [" << format_number(t.lo, 4) << ", "
                      << format_number(t.hi, 4) << "]: " << (t.ours >= t.lo && t.ours <= t.hi ? "within" : "outside")
                      << "\n";
    }
    int counts[6] = {0, 0, 0, 0, 0, 0};  // by ClaimStatus
    for (const auto& r : records_) {
        ++counts[static_cast<int>(r.status)];
        if (r.status == ClaimStatus::failed || r.status == ClaimStatus::fails)
            std::cerr << "FAILED " << r.kind << " " << r.id << ": paper " << r.paper_text << ", ours "
                      << format_number(r.ours) << ", tolerance " << format_number(r.tolerance, 3) << "\n";
    }
    std::cout << paper_ << "/" << artifact_ << ": " << counts[0] << " reproduced, " << counts[1] << " deviates, "
              << counts[2] << " depend on a choice, " << counts[3] << " failed";
    if (counts[4] + counts[5] > 0) std::cout << "; claims of ours: " << counts[4] << " hold, " << counts[5] << " fail";
    std::cout << "\n";
    return counts[3] + counts[5] > 0 ? 1 : 0;
}

}  // namespace cagd::repro
