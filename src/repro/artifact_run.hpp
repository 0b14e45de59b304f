#pragma once
// One run of one experiment (one paper artifact): loads the artifact's reference file,
// records a check per claim and a validation per independent recomputation, writes
//   results/<paper>/<artifact>.checks.csv   (claims and validations, stable formatting)
//   results/<paper>/<artifact>.meta         (title, section, sources, figures, notes)
// plus the data files the experiment asks for, and returns the exit code.
//
// Status of a claim (docs/reproduction.md):
//   reproduced  |ours − paper| ≤ tolerance
//   deviates    outside tolerance, the row names an erratum present in reference/ERRATA.md,
//               and the corrected statement holds: |ours − corrected_value| ≤ tolerance, or
//               (for a misprinted formula) the experiment's value computed with the corrected
//               formula, ours_corrected, satisfies |ours_corrected − paper| ≤ tolerance
//   depends     a claim checked under every choice the paper leaves open (a free constant, a fit
//               range, a threshold, a reading of the text; check_over_choices): reproduced or
//               deviates under our stated choice, but whether |ours − paper| ≤ tolerance holds
//               differs between the choices. The report gives the range of ours over the choices
//               and which choices decide. When every choice agrees, the stated status stands and
//               the claim is unconditional (its range is still shown).
//               The rule (docs/reproduction.md), enforced here: only alternatives the paper's text
//               allows decide (ChoiceKind::reading), and a threshold decides only when the claim's
//               reference row declares it (column `thresholds`: the stated one first, then the
//               allowed alternatives, each fixed before the run). An alternative that exists to
//               reach the printed number (a stop tuned within a tie, a minimiser assumed to stop
//               in another basin, a threshold added after a measurement) is a ChoiceKind::note:
//               shown beside the claim, never deciding. An undeclared threshold fails the claim.
//   failed      anything else, including a reference row the experiment never checked.
//   ours: holds / ours: fails   the verdict on a claim of ours (reference column origin = ours: a
//               statement we make where the paper prints none), within its tolerance or not; it is
//               counted apart from the paper's claims everywhere, and fails counts as failed.
// Any failed claim or validation makes finish() return 1; depends does not.
//
// Command line of every experiment: [--check] [--root DIR]. --check computes and checks
// everything but writes under a temporary directory instead of results/.
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "cagd/core/csv.hpp"
#include "cagd/io/csv_writer.hpp"
#include "repro/reference.hpp"

namespace cagd::repro {

// holds / fails: the verdict on a claim of ours (a reference row with origin "ours"), kept apart
// from the paper's; fails counts as a failure.
enum class ClaimStatus { reproduced, deviates, depends, failed, holds, fails };
const char* to_string(ClaimStatus s);

// The classification rule above, as a pure function (unit-tested).
ClaimStatus classify(const ReferenceRow& row, double ours, std::optional<double> ours_corrected,
                     bool erratum_documented);

// reading: an alternative the paper's text allows (it can make a claim `depends`); note: one that
// exists only to reach the printed number (reported beside the claim, never deciding).
enum class ChoiceKind { reading, note };

// One choice and our value under it. `tolerance`, when given, replaces the row's (a choice of
// threshold: "visible" = 0.1 % instead of 0.2 % of the diagonal); it must be one the row declares.
struct ChoiceValue {
    std::string label;  // "s0 = 0, L = 1, fit t in [0, 1]"
    double ours = 0.0;
    std::optional<double> tolerance{};
    ChoiceKind kind = ChoiceKind::reading;
};
// The status over choices (rule `depends` above): `stated` is the status under our stated choice;
// `within` says, for the stated choice and then each alternative, whether |ours − paper| ≤ its
// tolerance.
ClaimStatus classify_over_choices(ClaimStatus stated, const std::vector<bool>& within);

// The odds of a chance match (docs/reproduction.md) of an integer claim checked over choices: over
// the readings only (notes are never evidence), how many give `printed`, and the chance that some
// reading equals an integer drawn uniformly from [lowest, highest], the smallest range holding every
// reading's value: distinct / (highest − lowest + 1).
struct MatchOdds {
    int readings = 0, matching = 0, distinct = 0;  // readings; of them giving `printed`; distinct values
    long lowest = 0, highest = 0;                  // the range of the readings' values
    double chance = 0.0;                           // distinct / (highest − lowest + 1)
    // A match whose chance is at least this is consistent with chance (docs/reproduction.md).
    static constexpr double kConsistentWithChance = 0.05;
};
// InvalidInput when there is no reading or a reading's value is not an integer.
MatchOdds match_odds(const std::vector<ChoiceValue>& choices, double printed);

struct CheckRecord {
    std::string kind;  // "claim", "ours" (a claim of ours) or "validation"
    std::string id, description;
    double paper = 0.0, ours = 0.0, tolerance = 0.0;
    std::string paper_text, tolerance_reason, erratum;
    ClaimStatus status = ClaimStatus::failed;
    // Checked over choices: the range of ours over them (stated included) and, per verdict, which.
    std::string ours_range{}, choices{};
};

class ArtifactRun {
public:
    // section: the paper's section/equation used to order artifacts in the report ("2.1").
    // With --check the data go to a fresh temporary directory, removed with the run (ctest checks
    // the claims and leaves nothing behind); otherwise to <root>/results/<paper>.
    ArtifactRun(std::string paper, std::string artifact, std::string section, std::string title, int argc, char** argv);
    ~ArtifactRun();
    ArtifactRun(const ArtifactRun&) = delete;
    ArtifactRun& operator=(const ArtifactRun&) = delete;

    const Reference& reference() const { return reference_; }
    // Check claim `<paper>.<short_id>` of the reference file against our value.
    void check(const std::string& short_id, double ours);
    void check(const std::string& short_id, double ours, double ours_corrected);
    // A claim whose value depends on a choice the paper leaves open: ours under our stated choice
    // (named by `stated`, the value the report shows) and under every other allowed choice.
    void check_over_choices(const std::string& short_id, double ours, const std::string& stated,
                            const std::vector<ChoiceValue>& others);
    // A statement "measure < threshold" (a vague word of the paper made a number: "nearly the same"
    // = within 1 % of the diagonal): the thresholds come from the claim's reference row (column
    // `thresholds`, the stated one first), never from the experiment. The claim's value is 1 when
    // measure < threshold, else 0; the row's other thresholds are its alternatives, and those of
    // `note_thresholds` are shown as notes.
    void check_threshold(const std::string& short_id, double measure, const std::string& what);
    // An independent recomputation of a library value: |fast − reference| ≤ tolerance.
    void validate(const std::string& short_id, const std::string& description, double fast, double reference_value,
                  double tolerance, const std::string& tolerance_reason);

    // A timing claim (timing is never pass/fail and never byte-stable): `ours` is
    // tested against the interval [lo, hi] the paper's printed digits allow. It is written to
    // <root>/results/timing/<paper>_<artifact>.csv (not committed, not compared by CI) and listed
    // in the report without the measured value; the reference rows in `rows_used` (the printed
    // times it is derived from) count as checked.
    void timing(const std::string& short_id, const std::string& description, const std::vector<std::string>& rows_used,
                double paper_ratio, double lo, double hi, double ours);

    void figure(const std::string& name, const std::string& caption);
    void note(const std::string& text);
    std::string data_path(const std::string& file_name) const;  // where to write data
    // reference/<paper>/<file>: data transcribed from the paper (e.g. point tables).
    std::string reference_path(const std::string& file_name) const;
    // Where to keep an expensive intermediate (a lookup table) between runs:
    // <root>/build/cache/<paper>/<file>; never compared, never committed.
    std::string cache_path(const std::string& file_name) const;
    CsvWriter table(const std::string& file_name, const std::vector<std::string>& header) const;

    int finish();
    // The checks recorded so far, in order (tests read the statuses here).
    const std::vector<CheckRecord>& records() const { return records_; }

private:
    std::string paper_, artifact_, section_, title_, root_, out_dir_;
    bool check_mode_ = false;
    Reference reference_;
    std::set<std::string> errata_;
    std::vector<CheckRecord> records_;
    struct TimingRecord {
        std::string id, description;
        double paper = 0.0, lo = 0.0, hi = 0.0, ours = 0.0;
    };
    std::vector<TimingRecord> timings_;
    std::set<std::string> timing_rows_;
    std::vector<std::pair<std::string, std::string>> figures_;
    std::vector<std::string> notes_;
};

}  // namespace cagd::repro
