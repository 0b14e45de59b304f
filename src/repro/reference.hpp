#pragma once
// Reference files: reference/<paper>/<artifact>.csv — the claims of one paper artifact as
// transcribed from the paper, with provenance.
//
//   # paper: sb2_locality — M. Kuroda, …, IPSJ Journal; source: eq (13), section 3.1   ← '#' lines: provenance
//   id,paper_value,tolerance,tolerance_reason,erratum,corrected_value,description
//   sb2_locality.eq13.m4.w0,0.998621,5e-7,printed 6 decimals,,,weight of q_{i,0} for m = 4
//
// paper_value may be a decimal or an exact fraction a/b. erratum names an entry of
// reference/ERRATA.md; corrected_value (optional) is the value that entry derives. Optional
// columns: thresholds, note_thresholds (ArtifactRun::check_threshold); origin, stated (our claims).
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace cagd::repro {

struct ReferenceRow {
    std::string id;
    double paper_value = 0.0;
    std::string paper_text;  // as written in the file (e.g. "56/41")
    double tolerance = 0.0;
    std::string tolerance_reason;
    std::string erratum;  // empty if none
    std::optional<double> corrected_value;
    std::string description;
    // A claim "measure < threshold": the stated threshold first, then the alternatives the text
    // allows (column `thresholds`, ';'-separated), and thresholds shown only as notes (column
    // `note_thresholds`). Empty for other claims.
    std::vector<double> thresholds{}, note_thresholds{};
    // Whose statement the row is: the paper's (column `origin` empty or "paper"), or ours ("ours":
    // a statement we make where the paper prints no number, counted apart). An "ours" row says in
    // column `stated` whether it was written "before" or "after" a first measurement.
    bool ours = false;
    std::string stated{};
};

struct Reference {
    std::string path;
    std::vector<std::string> provenance;                   // the '#' lines, without '#'
    std::vector<ReferenceRow> rows;                        // file order
    const ReferenceRow& row(const std::string& id) const;  // InvalidInput if absent
};

// Throws InvalidInput naming the file and line on a malformed file (no provenance header,
// missing column, unparsable number, negative tolerance, duplicate id).
Reference load_reference(const std::string& path);

// An entry of ERRATA.md: its heading "## <id> — <what is wrong>".
struct Erratum {
    std::string id;
    std::string title;  // after the dash; empty if the heading has none
};
// The entries of ERRATA.md, in file order.
std::vector<Erratum> load_errata(const std::string& errata_path);
// Their ids.
std::vector<std::string> load_erratum_ids(const std::string& errata_path);

}  // namespace cagd::repro
