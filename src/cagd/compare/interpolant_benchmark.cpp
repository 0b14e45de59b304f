#include "cagd/compare/interpolant_benchmark.hpp"

#include <algorithm>
#include <cstdio>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include "cagd/core/checksum.hpp"
#include "cagd/core/csv.hpp"
#include "cagd/core/errors.hpp"
#include "cagd/core/version.hpp"

namespace cagd::compare {

namespace {

constexpr const char* kWho = "compare::merge_benchmark_parts";
constexpr const char* kFirstLine = "# cagd benchmark part";
// Distances at rounding level are drawn at this floor in convergence_<family>.dat (the plot is
// log-scaled; 0 is "exact").
constexpr double kDrawnFloor = 1e-17;

// ---- the part's fields: every value exactly ----

// A double in hexadecimal floating point ("%a"): strtod reads it back bit for bit.
std::string exact(double v) {
    char buf[48];
    std::snprintf(buf, sizeof buf, "%a", v);
    return buf;
}
std::string exact(const std::optional<double>& v) { return v ? exact(*v) : std::string(); }
// Text with its line breaks and '%' escaped, so that a record is one line whatever a note holds.
std::string escaped(const std::string& text) {
    std::string out;
    for (const char c : text) {
        if (c == '%')
            out += "%25";
        else if (c == '\n')
            out += "%0A";
        else if (c == '\r')
            out += "%0D";
        else
            out += c;
    }
    return out;
}

// The fields of one record, read in order; each read names the part, line and field when it fails.
class Fields {
public:
    Fields(std::vector<std::string> fields, std::string where) : fields_(std::move(fields)), where_(std::move(where)) {}
    std::size_t size() const { return fields_.size(); }
    const std::string& next() {
        if (at_ >= fields_.size())
            fail_input(kWho, where_ + ": " + std::to_string(fields_.size()) + " fields, too few");
        return fields_[at_++];
    }
    std::string text() {
        const std::string& f = next();
        std::string out;
        for (std::size_t i = 0; i < f.size(); ++i) {
            if (f[i] == '%' && f.compare(i, 3, "%25") == 0)
                out += '%', i += 2;
            else if (f[i] == '%' && f.compare(i, 3, "%0A") == 0)
                out += '\n', i += 2;
            else if (f[i] == '%' && f.compare(i, 3, "%0D") == 0)
                out += '\r', i += 2;
            else
                out += f[i];
        }
        return out;
    }
    double number() {
        const std::string& f = next();
        double v = 0.0;
        if (!parse_decimal(f, v) || !std::isfinite(v))
            fail_input(kWho,
                       where_ + ": field " + std::to_string(at_) + " \"" + excerpt(f) + "\" is not a finite number");
        return v;
    }
    std::optional<double> optional_number() {
        if (at_ < fields_.size() && fields_[at_].empty()) return ++at_, std::nullopt;
        return number();
    }
    long integer(long lo, long hi) {
        const std::string& f = next();
        std::size_t used = 0;
        long v = 0;
        try {
            v = std::stol(f, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (used != f.size() || f.empty() || v < lo || v > hi)
            fail_input(kWho, where_ + ": field " + std::to_string(at_) + " \"" + excerpt(f) +
                                 "\" is not a whole number in " + std::to_string(lo) + ".." + std::to_string(hi));
        return v;
    }
    void end() const {
        if (at_ != fields_.size())
            fail_input(
                kWho, where_ + ": " + std::to_string(fields_.size()) + " fields, " + std::to_string(at_) + " expected");
    }

private:
    std::vector<std::string> fields_;
    std::string where_;
    std::size_t at_ = 0;
};

constexpr long kMaxCount = 1L << 30;  // more units than any plan has (and a long on every platform)

void put_shape(std::vector<std::string>& f, const ShapeMeasures& s) {
    f.insert(f.end(),
             {exact(s.bending), exact(s.variation), exact(s.max_curvature), std::to_string(s.curvature_extrema),
              exact(s.g2_defect), std::to_string(s.inflections), std::to_string(s.unimplied_inflections)});
}
ShapeMeasures get_shape(Fields& f) {
    ShapeMeasures s;
    s.bending = f.number(), s.variation = f.number(), s.max_curvature = f.number();
    s.curvature_extrema = static_cast<int>(f.integer(0, kMaxCount));
    s.g2_defect = f.number();
    s.inflections = static_cast<int>(f.integer(0, kMaxCount));
    s.unimplied_inflections = static_cast<int>(f.integer(0, kMaxCount));
    return s;
}
std::string line(const std::vector<std::string>& fields) { return csv_record(fields); }

std::string truth_record(long index, const TruthRun& r) {
    std::vector<std::string> f{"truth",
                               std::to_string(index),
                               escaped(r.family),
                               to_string(r.spacing),
                               r.closed ? "1" : "0",
                               std::to_string(r.n),
                               escaped(r.method),
                               escaped(to_string(r.status)),
                               escaped(r.note)};
    for (int e = 0; e < 5; ++e) f.push_back(exact(truth_error(r.errors, e)));
    put_shape(f, r.shape);
    put_shape(f, r.truth_shape);
    f.push_back(exact(r.extensionality));
    return line(f);
}
AttemptStatus read_status(Fields& f, const std::string& where) {
    const std::string text = f.text();
    const std::optional<AttemptStatus> s = attempt_status_from_string(text);
    if (!s)
        fail_input(kWho, where + ": status \"" + excerpt(text) +
                             "\" is none of ok, not applicable, refused, no result, cusp, loops, failed");
    return *s;
}
TruthRun read_truth(Fields& f, const std::string& where) {
    TruthRun r;
    r.family = f.text();
    const std::string spacing = f.text();
    if (spacing != to_string(TruthSpacing::uniform) && spacing != to_string(TruthSpacing::nonuniform))
        fail_input(kWho, where + ": spacing \"" + excerpt(spacing) + "\" is neither uniform nor non-uniform");
    r.spacing = spacing == to_string(TruthSpacing::uniform) ? TruthSpacing::uniform : TruthSpacing::nonuniform;
    r.closed = f.integer(0, 1) == 1;
    r.n = static_cast<int>(f.integer(0, 100000));
    r.method = f.text(), r.status = read_status(f, where), r.note = f.text();
    r.errors.distance = f.number(), r.errors.tangent_angle = f.number(), r.errors.curvature_max = f.number(),
    r.errors.curvature_l2 = f.number(), r.errors.length = f.number();
    r.shape = get_shape(f);
    r.truth_shape = get_shape(f);
    r.extensionality = f.optional_number();
    return r;
}

std::string classic_record(long index, const ClassicRun& r) {
    std::vector<std::string> f{"classic",         std::to_string(index),        escaped(r.data_set),
                               escaped(r.group),  std::to_string(r.n),          r.closed ? "1" : "0",
                               escaped(r.method), escaped(to_string(r.status)), escaped(r.note)};
    put_shape(f, r.shape);
    f.push_back(exact(r.overshoot));
    f.push_back(exact(r.extensionality));
    return line(f);
}
ClassicRun read_classic(Fields& f) {
    ClassicRun r;
    r.data_set = f.text(), r.group = f.text();
    r.n = static_cast<int>(f.integer(0, 100000000));
    r.closed = f.integer(0, 1) == 1;
    r.method = f.text(), r.status = read_status(f, "a classic run"), r.note = f.text();
    r.shape = get_shape(f);
    r.overshoot = f.number();
    r.extensionality = f.optional_number();
    return r;
}

std::string random_record(long index, const RandomSetSummary& s) {
    std::string seconds;
    for (const double t : s.seconds) (seconds += seconds.empty() ? "" : ";") += exact(t);
    return line({"random", std::to_string(index), to_string(s.kind), std::to_string(s.n), escaped(s.method),
                 std::to_string(s.sets), std::to_string(s.ok), std::to_string(s.no_solution),
                 std::to_string(s.no_convergence), std::to_string(s.not_representable), std::to_string(s.refused),
                 std::to_string(s.not_applicable), seconds});
}
RandomSetSummary read_random(Fields& f, const std::string& where) {
    RandomSetSummary s;
    const std::string kind = f.text();
    if (kind != to_string(RandomSetKind::walk) && kind != to_string(RandomSetKind::scatter))
        fail_input(kWho, where + ": kind \"" + excerpt(kind) + "\" is neither walk nor scatter");
    s.kind = kind == to_string(RandomSetKind::walk) ? RandomSetKind::walk : RandomSetKind::scatter;
    s.n = static_cast<int>(f.integer(0, 100000));
    s.method = f.text();
    s.sets = static_cast<int>(f.integer(0, 1L << 30)), s.ok = static_cast<int>(f.integer(0, 1L << 30)),
    s.no_solution = static_cast<int>(f.integer(0, 1L << 30));
    s.no_convergence = static_cast<int>(f.integer(0, 1L << 30));
    s.not_representable = static_cast<int>(f.integer(0, 1L << 30));
    s.refused = static_cast<int>(f.integer(0, 1L << 30)), s.not_applicable = static_cast<int>(f.integer(0, 1L << 30));
    std::stringstream seconds(f.text());
    for (std::string t; std::getline(seconds, t, ';');) {
        double v = 0.0;
        if (!parse_decimal(t, v)) fail_input(kWho, where + ": a run time \"" + excerpt(t) + "\" is not a number");
        s.seconds.push_back(v);
    }
    if (s.ok + s.no_result() + s.refused + s.not_applicable != s.sets ||
        static_cast<int>(s.seconds.size()) != s.sets - s.not_applicable)
        fail_input(kWho,
                   where + ": the counts of " + s.method + " do not add up to its " + std::to_string(s.sets) + " sets");
    return s;
}

// The plan as text: everything that decides the results.
std::string plan_text(const BenchmarkPlan& p) {
    std::ostringstream t;
    t << "library " << library_version() << "\nsizes";
    for (const int n : p.truth.sizes) t << ' ' << n;
    t << "\nfamilies";
    if (p.truth.families.empty())
        for (const TruthFamily& f : truth_families()) t << ' ' << f.name;
    for (const std::string& f : p.truth.families) t << ' ' << find_truth_family(f).name;
    t << "\nconfigurations";
    if (p.truth.methods.empty())
        for (const methods::Configuration& c : methods::configurations()) t << ' ' << c.name;
    for (const std::string& m : p.truth.methods) t << ' ' << methods::find_configuration(m).name;
    t << "\nrandom " << p.random.sets << " sets, scattered up to " << p.random.scatter_max_points << ", sizes";
    for (const int n : p.random.sizes) t << ' ' << n;
    t << "\nrandom configurations";
    for (const std::string& m : p.random.methods) t << ' ' << methods::find_configuration(m).name;
    for (const ClassicDataSet& d : p.classic) {
        t << "\nclassic " << d.name << ' ' << d.group << ' ' << d.closed << ' ' << d.source << ':';
        for (Eigen::Index i = 0; i < d.points.rows(); ++i)
            for (Eigen::Index j = 0; j < d.points.cols(); ++j) t << ' ' << exact(d.points(i, j));
    }
    return t.str();
}

}  // namespace

BenchmarkResults run_benchmark(const BenchmarkPlan& plan, const WorkShare& share, int threads) {
    check_work_share(share, "compare::run_benchmark");
    BenchmarkResults r;
    TruthBenchmarkOptions truth = plan.truth;
    truth.share = share, truth.threads = threads;
    r.truth = run_truth_benchmark(truth);
    if (!plan.classic.empty()) r.classic = run_classic_benchmark(plan.classic, plan.truth.methods, threads, share);
    if (plan.random.sets > 0) {
        RandomSetOptions random = plan.random;
        random.share = share, random.threads = threads;
        r.random = run_random_sets(random);
    }
    return r;
}

std::string benchmark_plan_fingerprint(const BenchmarkPlan& plan) { return fnv1a64_hex(plan_text(plan)); }

std::string benchmark_part_text(const BenchmarkPlan& plan, const WorkShare& share, const BenchmarkResults& results) {
    check_work_share(share, "compare::benchmark_part_text");
    std::string text = std::string(kFirstLine) + "\npart," + std::to_string(share.index + 1) + "," +
                       std::to_string(share.count) + "\nplan," + benchmark_plan_fingerprint(plan) + "\nunits," +
                       std::to_string(results.truth.size()) + "," + std::to_string(results.classic.size()) + "," +
                       std::to_string(results.random.size()) + "\n";
    for (std::size_t i = 0; i < results.truth.size(); ++i)
        if (share.owns(static_cast<long>(i))) text += truth_record(static_cast<long>(i), results.truth[i]);
    for (std::size_t i = 0; i < results.classic.size(); ++i)
        if (share.owns(static_cast<long>(i))) text += classic_record(static_cast<long>(i), results.classic[i]);
    for (std::size_t i = 0; i < results.random.size(); ++i)
        text += random_record(static_cast<long>(i), results.random[i]);
    return text + checksum_line(text);
}

BenchmarkResults merge_benchmark_parts(const BenchmarkPlan& plan,
                                       const std::vector<std::pair<std::string, std::string>>& parts) {
    if (parts.empty()) fail_input(kWho, "no parts to merge");
    const std::string fingerprint = benchmark_plan_fingerprint(plan);
    BenchmarkResults out;
    std::vector<char> truth_seen, classic_seen;
    std::vector<std::string> part_seen;  // the name of the part of each number, once seen
    long count = -1, truth_units = -1, classic_units = -1, random_units = -1;
    for (const auto& part : parts) {
        const std::string& name =
            part.first;  // not a structured binding: clang 14 (Emscripten's) cannot capture one in a lambda
        const std::string_view content = checked_content(part.second, name);
        std::istringstream in{std::string(content)};
        std::string l;
        int line_no = 0;
        const auto next_line = [&](const char* what) {
            if (!std::getline(in, l)) fail_input(kWho, name + ": ends before " + what);
            ++line_no;
        };
        const auto where = [&] { return name + ":" + std::to_string(line_no); };
        next_line("its first line");
        if (l != kFirstLine)
            fail_input(kWho,
                       name + ":1: \"" + excerpt(l) + "\" is not \"" + kFirstLine + "\": not a part of cagd benchmark");
        next_line("its part line");
        Fields head(split_csv_line(l), where());
        if (head.next() != "part") fail_input(kWho, where() + ": expected part,<k>,<N>");
        const long k = head.integer(1, 1L << 20), n = head.integer(1, 1L << 20);
        head.end();
        if (k > n) fail_input(kWho, where() + ": part " + std::to_string(k) + " of " + std::to_string(n));
        if (n > static_cast<long>(parts.size())) {  // before anything is sized from it: the first one missing
            std::set<long> given;
            for (const auto& other : parts) {
                const std::size_t second = other.second.find('\n');
                long a = 0, b = 0;
                if (second != std::string::npos &&
                    std::sscanf(other.second.c_str() + second + 1, "part,%ld,%ld", &a, &b) == 2 && b == n)
                    given.insert(a);
            }
            long first = 1;
            while (given.count(first) > 0) ++first;
            fail_input(kWho, "part " + std::to_string(first) + " of " + std::to_string(n) + " is missing (" +
                                 std::to_string(parts.size()) + " parts given)");
        }
        if (count >= 0 && n != count)
            fail_input(kWho, where() + ": a part of " + std::to_string(n) + ", the others of " + std::to_string(count));
        count = n;
        part_seen.resize(static_cast<std::size_t>(n));
        if (!part_seen[static_cast<std::size_t>(k - 1)].empty())
            fail_input(kWho, name + ": part " + std::to_string(k) + " of " + std::to_string(n) + " again (first in " +
                                 part_seen[static_cast<std::size_t>(k - 1)] + ")");
        part_seen[static_cast<std::size_t>(k - 1)] = name;
        const WorkShare share{static_cast<int>(k - 1), static_cast<int>(n)};
        next_line("its plan line");
        if (l != "plan," + fingerprint)
            fail_input(kWho, where() + ": \"" + excerpt(l) +
                                 "\": the part was computed for another plan (sizes, families, methods, random sets, "
                                 "classic data) or another library version than this one (plan," +
                                 fingerprint + ")");
        next_line("its units line");
        Fields units(split_csv_line(l), where());
        if (units.next() != "units") fail_input(kWho, where() + ": expected units,<truth>,<classic>,<random>");
        const long t = units.integer(0, kMaxCount), c = units.integer(0, kMaxCount), r = units.integer(0, kMaxCount);
        units.end();
        // The part holds its share of each kind's units, and every random summary: its records,
        // counted before anything is sized from the units line.
        const auto held = [&](const std::string& kind) {
            long count_of_kind = 0;
            const std::string start = "\n" + kind + ",";
            for (std::size_t at = content.find(start); at != std::string::npos; at = content.find(start, at + 1))
                ++count_of_kind;
            return count_of_kind;
        };
        const auto owned = [&](long units_of_kind) { return units_of_kind > k - 1 ? (units_of_kind - k) / n + 1 : 0L; };
        if (held("truth") != owned(t) || held("classic") != owned(c) || held("random") != r)
            fail_input(kWho, where() + ": " + l + " declares " + std::to_string(owned(t)) + " truth, " +
                                 std::to_string(owned(c)) + " classic and " + std::to_string(r) +
                                 " random records for part " + std::to_string(k) + " of " + std::to_string(n) +
                                 "; it holds " + std::to_string(held("truth")) + ", " +
                                 std::to_string(held("classic")) + " and " + std::to_string(held("random")));
        if (truth_units < 0) {
            truth_units = t, classic_units = c, random_units = r;
            out.truth.resize(static_cast<std::size_t>(t)), truth_seen.assign(static_cast<std::size_t>(t), 0);
            out.classic.resize(static_cast<std::size_t>(c)), classic_seen.assign(static_cast<std::size_t>(c), 0);
        } else if (t != truth_units || c != classic_units || r != random_units) {
            fail_input(kWho, where() + ": " + l + " differs from the other parts' units");
        }
        std::vector<RandomSetSummary> random;
        while (std::getline(in, l)) {
            ++line_no;
            Fields f(split_csv_line(l), where());
            const std::string kind = f.next();
            if (kind != "truth" && kind != "classic" && kind != "random")
                fail_input(kWho, where() + ": a record \"" + excerpt(kind) + "\": expected truth, classic or random");
            const long limit = kind == "truth" ? truth_units : kind == "classic" ? classic_units : random_units;
            if (limit == 0) fail_input(kWho, where() + ": a " + kind + " record where the units line has none");
            const long index = f.integer(0, limit - 1);
            if (kind == "random") {
                if (index != static_cast<long>(random.size()))
                    fail_input(kWho, where() + ": random summary " + std::to_string(index) + " out of order");
                random.push_back(read_random(f, where()));
            } else {
                if (!share.owns(index))
                    fail_input(kWho, where() + ": " + kind + " run " + std::to_string(index) + " is not part " +
                                         std::to_string(k) + "'s");
                std::vector<char>& seen = kind == "truth" ? truth_seen : classic_seen;
                if (seen[static_cast<std::size_t>(index)])
                    fail_input(kWho, where() + ": " + kind + " run " + std::to_string(index) + " twice");
                seen[static_cast<std::size_t>(index)] = 1;
                if (kind == "truth")
                    out.truth[static_cast<std::size_t>(index)] = read_truth(f, where());
                else
                    out.classic[static_cast<std::size_t>(index)] = read_classic(f);
            }
            f.end();
        }
        if (static_cast<long>(random.size()) != random_units)
            fail_input(kWho, name + ": " + std::to_string(random.size()) + " random summaries of " +
                                 std::to_string(random_units));
        if (out.random.empty()) {
            out.random = std::move(random);
        } else {
            try {
                merge_random_sets(out.random, random);
            } catch (const std::logic_error& e) {
                fail_input(kWho, name + ": its random summaries are not the other parts': " + e.what());
            }
        }
    }
    for (long k = 0; k < count; ++k)
        if (part_seen[static_cast<std::size_t>(k)].empty())
            fail_input(kWho, "part " + std::to_string(k + 1) + " of " + std::to_string(count) + " is missing");
    const auto all_seen = [&](const std::vector<char>& seen, const char* kind) {
        const auto missing = std::find(seen.begin(), seen.end(), 0);
        if (missing != seen.end())
            fail_input(kWho, std::string(kind) + " run " + std::to_string(missing - seen.begin()) + " is in no part");
    };
    all_seen(truth_seen, "truth");
    all_seen(classic_seen, "classic");
    for (const RandomSetSummary& s : out.random)
        if (s.sets != plan.random.sets)
            fail_input(kWho, "the parts hold " + std::to_string(s.sets) + " random sets of " + s.method + ", not " +
                                 std::to_string(plan.random.sets));
    return out;
}

std::vector<std::pair<std::string, std::string>> benchmark_files(const BenchmarkPlan& plan,
                                                                 const BenchmarkResults& results) {
    std::vector<std::pair<std::string, std::string>> files;
    const std::vector<ConvergenceOrder> orders = convergence_orders(results.truth);
    if (!plan.classic.empty()) {
        files.emplace_back("classic_runs.csv", csv_table(classic_runs_header(), classic_runs_rows(results.classic)));
        files.emplace_back("classic.md", classic_tables_markdown(results.classic, plan.classic));
    }
    if (plan.random.sets > 0)
        files.emplace_back("random_sets.csv", csv_table(random_sets_header(), random_sets_rows(results.random)));
    files.emplace_back("truth_runs.csv", csv_table(truth_runs_header(), truth_runs_rows(results.truth)));
    files.emplace_back("convergence_orders.csv",
                       csv_table(convergence_orders_header(), convergence_orders_rows(orders)));
    files.emplace_back("leaderboard.md", truth_leaderboard_markdown(results.truth, orders) +
                                             classic_summary_markdown(results.classic, plan.classic) +
                                             random_sets_markdown(results.random));
    for (const TruthFamily& family : truth_families()) {
        // The configurations in the runs' order, each a block of its sizes (distance against n;
        // uniform spacing, closed where the family is): scripts/plot/benchmark_fig_convergence.gp.
        std::vector<std::string> order;
        for (const TruthRun& r : results.truth)
            if (r.family == family.name && std::find(order.begin(), order.end(), r.method) == order.end())
                order.push_back(r.method);
        if (order.empty()) continue;
        std::ostringstream f;
        for (std::size_t m = 0; m < order.size(); ++m) {
            f << (m ? "\n\n" : "") << "n \"" << order[m] << "\" distance\n";
            for (const TruthRun& r : results.truth)
                if (r.family == family.name && r.method == order[m] && r.spacing == TruthSpacing::uniform &&
                    r.closed == family.closed && r.status == AttemptStatus::ok)
                    f << r.n << " " << r.n << " " << format_number(std::max(r.errors.distance, kDrawnFloor), 6) << "\n";
        }
        files.emplace_back("convergence_" + family.name + ".dat", f.str());
    }
    return files;
}

std::string benchmark_timing_csv(const BenchmarkResults& results) {
    return csv_table(random_set_timing_header(), random_set_timing_rows(results.random));
}

}  // namespace cagd::compare
