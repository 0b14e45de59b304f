#include "repro/reference.hpp"

#include <algorithm>
#include <fstream>
#include <set>

#include "cagd/core/csv.hpp"
#include "cagd/core/errors.hpp"

namespace cagd::repro {

const ReferenceRow& Reference::row(const std::string& id) const {
    for (const auto& r : rows)
        if (r.id == id) return r;
    fail_input("cagd::repro::Reference::row", "no claim '" + id + "' in " + path);
}

Reference load_reference(const std::string& path) {
    const std::string who = "cagd::repro::load_reference";
    std::ifstream in(path);
    if (!in) fail_input(who, "cannot read reference file '" + path + "'");
    Reference ref;
    ref.path = path;
    std::string line;
    std::vector<std::string> header;
    std::set<std::string> ids;
    int line_no = 0;
    while (std::getline(in, line)) {
        ++line_no;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.empty()) continue;
        if (line[0] == '#') {
            const auto b = line.find_first_not_of("# ");
            ref.provenance.push_back(b == std::string::npos ? "" : line.substr(b));
            continue;
        }
        const auto where = path + ":" + std::to_string(line_no);
        auto fields = split_csv_line(line);
        if (header.empty()) {
            header = fields;
            for (const char* required : {"id", "paper_value", "tolerance", "tolerance_reason"}) {
                bool found = false;
                for (const auto& h : header) found = found || h == required;
                if (!found) fail_input(who, where + ": header lacks column '" + required + "'");
            }
            continue;
        }
        if (fields.size() != header.size())
            fail_input(who, where + ": " + std::to_string(fields.size()) + " fields, header has " +
                                std::to_string(header.size()));
        ReferenceRow r;
        for (std::size_t i = 0; i < header.size(); ++i) {
            const std::string& h = header[i];
            const std::string& v = fields[i];
            try {
                if (h == "id")
                    r.id = v;
                else if (h == "paper_value") {
                    r.paper_value = parse_number(v);
                    r.paper_text = v;
                } else if (h == "tolerance")
                    r.tolerance = parse_number(v);
                else if (h == "tolerance_reason")
                    r.tolerance_reason = v;
                else if (h == "erratum")
                    r.erratum = v;
                else if (h == "corrected_value") {
                    if (!v.empty()) r.corrected_value = parse_number(v);
                } else if (h == "description")
                    r.description = v;
                else if (h == "origin") {
                    if (v != "" && v != "paper" && v != "ours")
                        fail_input(who, where + ": column 'origin' is '" + v + "'; allowed: paper, ours (or empty)");
                    r.ours = v == "ours";
                } else if (h == "stated") {
                    if (v != "" && v != "before" && v != "after")
                        fail_input(who, where + ": column 'stated' is '" + v +
                                            "'; allowed: before, after (a first measurement)");
                    r.stated = v;
                } else if (h == "thresholds" || h == "note_thresholds") {
                    std::vector<double>& out = h == "thresholds" ? r.thresholds : r.note_thresholds;
                    std::size_t start = 0;
                    while (start <= v.size() && !v.empty()) {
                        const std::size_t end = std::min(v.find(';', start), v.size());
                        const double t = parse_number(v.substr(start, end - start));
                        if (!(t > 0.0))
                            fail_input(who, where + ": column '" + h + "': threshold " + v.substr(start, end - start) +
                                                " must be > 0");
                        out.push_back(t);
                        start = end + 1;
                    }
                }
            } catch (const InvalidInput& e) {
                fail_input(who, where + ": column '" + h + "': " + e.what());
            }
        }
        if (r.id.empty()) fail_input(who, where + ": empty id");
        if (!(r.tolerance >= 0.0)) fail_input(who, where + ": tolerance must be >= 0");
        if (r.tolerance_reason.empty()) fail_input(who, where + ": tolerance_reason is empty");
        if (r.ours && r.stated.empty())
            fail_input(who, where +
                                ": a claim of ours must say in column 'stated' whether it was written before or after "
                                "a first measurement");
        if (!ids.insert(r.id).second) fail_input(who, where + ": duplicate id '" + r.id + "'");
        ref.rows.push_back(r);
    }
    if (ref.provenance.empty()) fail_input(who, path + ": no '#' provenance header");
    if (header.empty()) fail_input(who, path + ": no header line");
    return ref;
}

std::vector<Erratum> load_errata(const std::string& errata_path) {
    std::ifstream in(errata_path);
    if (!in) fail_input("cagd::repro::load_errata", "cannot read '" + errata_path + "'");
    std::vector<Erratum> errata;
    std::string line;
    const std::string dash = " — ";
    while (std::getline(in, line)) {
        if (line.rfind("## ", 0) != 0) continue;
        const auto end = line.find_first_of(" \t:", 3);
        Erratum e{line.substr(3, end == std::string::npos ? std::string::npos : end - 3), ""};
        if (const auto d = line.find(dash); d != std::string::npos) e.title = line.substr(d + dash.size());
        errata.push_back(std::move(e));
    }
    return errata;
}

std::vector<std::string> load_erratum_ids(const std::string& errata_path) {
    std::vector<std::string> ids;
    for (Erratum& e : load_errata(errata_path)) ids.push_back(std::move(e.id));
    return ids;
}

}  // namespace cagd::repro
