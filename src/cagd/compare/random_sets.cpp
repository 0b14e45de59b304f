#include "cagd/compare/random_sets.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <random>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "cagd/compare/interpolation_attempt.hpp"
#include "cagd/core/csv.hpp"
#include "cagd/core/errors.hpp"
#include "cagd/core/parallel.hpp"
#include "cagd/core/random_walk.hpp"
#include "cagd/methods/method_registry.hpp"

namespace cagd::compare {

const char* to_string(RandomSetKind kind) { return kind == RandomSetKind::walk ? "walk" : "scatter"; }

PointList random_set(RandomSetKind kind, int n, unsigned seed) {
    if (n < 2) fail_input("cagd::compare::random_set", "needs n ≥ 2 points, got " + std::to_string(n));
    if (kind == RandomSetKind::walk) return random_walk(n, seed, 0.1, 2.0, 1.0);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> coordinate(0.0, 1.0);
    PointList p(n, 2);
    for (int i = 0; i < n; ++i) {
        const double x = coordinate(rng);  // x before y on every platform
        p.row(i) << x, coordinate(rng);
    }
    return p;
}

double RandomSetSummary::failure_rate() const {
    const int applicable = sets - not_applicable;
    return applicable > 0 ? static_cast<double>(no_result() + refused) / applicable : 0.0;
}

std::vector<RandomSetSummary> run_random_sets(const RandomSetOptions& o) {
    const char* who = "cagd::compare::run_random_sets";
    if (o.sets < 1) fail_input(who, "sets = " + std::to_string(o.sets) + "; at least 1");
    for (const int n : o.sizes)
        if (n < 3) fail_input(who, "size " + std::to_string(n) + "; each size needs at least 3 points");
    check_work_share(o.share, who);
    if (o.scatter_max_points < 0)
        fail_input(who, "scatter_max_points = " + std::to_string(o.scatter_max_points) + "; at least 0");
    std::vector<methods::Configuration> configurations;
    for (const std::string& name : o.methods) configurations.push_back(methods::find_configuration(name));
    if (o.methods.empty()) configurations = methods::configurations();
    // What the builds share (the pseudo-spline's tables) is loaded before any timing.
    for (const methods::Configuration& c : configurations)
        if (c.method->prepare) c.method->prepare(c.values, 2);

    // The (kind, size) cases: walks at every size, scattered points up to scatter_max_points.
    std::vector<std::pair<RandomSetKind, int>> cases;
    for (const RandomSetKind kind : {RandomSetKind::walk, RandomSetKind::scatter})
        for (const int n : o.sizes)
            if (kind == RandomSetKind::walk || n <= o.scatter_max_points) cases.emplace_back(kind, n);
    std::vector<RandomSetSummary> out;
    for (const auto& [kind, n] : cases)
        for (const methods::Configuration& c : configurations)
            out.push_back({.kind = kind, .n = n, .method = c.name, .seconds = {}});
    // One task per (case, set): its points made once, every configuration on them.
    struct SetOutcome {
        AttemptStatus status = AttemptStatus::ok;
        Status outcome = Status::ok;  // no result: the method's returned status
        double seconds = 0.0;
    };
    const std::size_t per_set = configurations.size();
    const long tasks = static_cast<long>(cases.size()) * o.sets;
    std::vector<SetOutcome> outcomes(static_cast<std::size_t>(tasks) * per_set);
    parallel_for(tasks, o.threads > 0 ? o.threads : hardware_threads(), [&](long task) {
        if (!o.share.owns(task)) return;
        const auto& [kind, n] = cases[static_cast<std::size_t>(task / o.sets)];
        const PointList points = random_set(kind, n, static_cast<unsigned>(task % o.sets));
        for (std::size_t m = 0; m < per_set; ++m) {
            SetOutcome& r = outcomes[static_cast<std::size_t>(task) * per_set + m];
            // Timed around the whole attempt (the applicability check is a few comparisons).
            const auto start = std::chrono::steady_clock::now();
            const InterpolationAttempt attempt = attempt_interpolation(configurations[m], points, false);
            r.status = attempt.status, r.outcome = attempt.result.outcome.status;
            r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        }
    });
    for (long task = 0; task < tasks; ++task) {
        if (!o.share.owns(task)) continue;
        const long block = task / o.sets;  // the case, in the order of `out`
        for (std::size_t m = 0; m < per_set; ++m) {
            RandomSetSummary& s = out[static_cast<std::size_t>(block) * per_set + m];
            ++s.sets;
            const SetOutcome& r = outcomes[static_cast<std::size_t>(task) * per_set + m];
            if (r.status == AttemptStatus::not_applicable) {
                ++s.not_applicable;
                continue;
            }
            if (r.status == AttemptStatus::ok)
                ++s.ok;
            else if (r.status != AttemptStatus::no_result)
                ++s.refused;
            else
                ++(r.outcome == Status::no_solution      ? s.no_solution
                   : r.outcome == Status::no_convergence ? s.no_convergence
                                                         : s.not_representable);
            s.seconds.push_back(r.seconds);
        }
    }
    return out;
}

void merge_random_sets(std::vector<RandomSetSummary>& total, const std::vector<RandomSetSummary>& part) {
    if (part.size() != total.size())
        throw std::logic_error("compare::merge_random_sets: " + std::to_string(part.size()) + " summaries into " +
                               std::to_string(total.size()));
    for (std::size_t i = 0; i < total.size(); ++i) {
        RandomSetSummary& t = total[i];
        const RandomSetSummary& p = part[i];
        if (p.kind != t.kind || p.n != t.n || p.method != t.method)
            throw std::logic_error("compare::merge_random_sets: summary " + std::to_string(i) + " is " + p.method +
                                   ", not " + t.method);
        t.sets += p.sets, t.ok += p.ok, t.no_solution += p.no_solution, t.no_convergence += p.no_convergence,
            t.not_representable += p.not_representable, t.refused += p.refused, t.not_applicable += p.not_applicable;
        t.seconds.insert(t.seconds.end(), p.seconds.begin(), p.seconds.end());
    }
}

std::vector<std::string> random_sets_header() {
    return {"kind",
            "n",
            "method",
            "sets",
            "ok",
            "no_solution",
            "no_convergence",
            "not_representable",
            "refused",
            "not_applicable",
            "failure_rate"};
}

std::vector<std::vector<std::string>> random_sets_rows(const std::vector<RandomSetSummary>& summaries) {
    std::vector<std::vector<std::string>> rows;
    for (const RandomSetSummary& s : summaries)
        rows.push_back({to_string(s.kind), std::to_string(s.n), s.method, std::to_string(s.sets), std::to_string(s.ok),
                        std::to_string(s.no_solution), std::to_string(s.no_convergence),
                        std::to_string(s.not_representable), std::to_string(s.refused),
                        std::to_string(s.not_applicable), format_number(s.failure_rate(), 6)});
    return rows;
}

std::vector<std::string> random_set_timing_header() {
    return {"kind", "n", "method", "runs", "median_seconds", "p90_seconds", "max_seconds"};
}

std::vector<std::vector<std::string>> random_set_timing_rows(const std::vector<RandomSetSummary>& summaries) {
    std::vector<std::vector<std::string>> rows;
    for (const RandomSetSummary& s : summaries) {
        std::vector<double> t = s.seconds;
        std::sort(t.begin(), t.end());
        // Nearest rank: the smallest value with at least q of the runs at or below it.
        const auto rank = [&](double q) {
            return t.empty() ? std::string()
                             : format_number(
                                   t[static_cast<std::size_t>(std::ceil(q * static_cast<double>(t.size()))) - 1], 4);
        };
        rows.push_back({to_string(s.kind), std::to_string(s.n), s.method, std::to_string(t.size()), rank(0.5),
                        rank(0.9), t.empty() ? std::string() : format_number(t.back(), 4)});
    }
    return rows;
}

namespace {
// "2 no solution, 47 no convergence, 0 refused" (not representable only where it occurs).
std::string failure_classes(const RandomSetSummary& s) {
    std::string text =
        std::to_string(s.no_solution) + " no solution, " + std::to_string(s.no_convergence) + " no convergence, ";
    if (s.not_representable > 0) text += std::to_string(s.not_representable) + " not representable, ";
    return text + std::to_string(s.refused) + " refused";
}
}  // namespace

std::string random_sets_markdown(const std::vector<RandomSetSummary>& summaries) {
    std::ostringstream s;
    if (summaries.empty()) return "";
    s << "\n#### Failure rates on seeded random sets\n\n"
      << summaries.front().sets
      << " sets per kind and size, each interpolated as an open curve by every configuration "
         "(compare/random_sets.hpp). "
         "*walk*: chords in [0.1, 2], turns within ±1 rad; *scatter*: points uniform in the unit square (at the "
         "smaller sizes only: "
         "beyond them nearly every set defeats the two Newton methods). A failure is no curve "
         "(a returned status: *no solution* when the method showed that none exists, *no convergence* when its solver "
         "failed, which shows nothing about the data) or a refusal (the method's own input check); not applicable "
         "sets are left out of the rate. "
         "Run times are not deterministic, so they stay out of these counts: `cagd benchmark --timing-out FILE` writes "
         "them "
         "(`make benchmark` and `make reproduce`: results/timing/benchmark_random_sets.csv).\n";
    for (const RandomSetKind kind : {RandomSetKind::walk, RandomSetKind::scatter}) {
        std::vector<int> sizes;
        for (const RandomSetSummary& r : summaries)
            if (r.kind == kind && std::find(sizes.begin(), sizes.end(), r.n) == sizes.end()) sizes.push_back(r.n);
        if (sizes.empty()) continue;
        s << "\n*" << to_string(kind) << "*\n\n| configuration |";
        for (const int n : sizes) s << " n = " << n << " |";
        s << " failures over all sizes |\n|---|";
        for (std::size_t i = 0; i < sizes.size(); ++i) s << "---:|";
        s << "---|\n";
        std::vector<std::string> never;
        std::vector<std::string> methods;
        for (const RandomSetSummary& r : summaries)
            if (r.kind == kind && std::find(methods.begin(), methods.end(), r.method) == methods.end())
                methods.push_back(r.method);
        for (const std::string& m : methods) {
            std::ostringstream line;
            bool fails = false;
            RandomSetSummary all;  // the counts over all sizes
            line << "| " << m << " |";
            for (const int n : sizes)
                for (const RandomSetSummary& r : summaries)
                    if (r.kind == kind && r.n == n && r.method == m) {
                        if (r.sets == r.not_applicable) {
                            line << " not applicable |";
                            continue;
                        }
                        all.sets += r.sets - r.not_applicable;
                        all.no_solution += r.no_solution, all.no_convergence += r.no_convergence;
                        all.not_representable += r.not_representable, all.refused += r.refused;
                        fails = fails || r.no_result() + r.refused > 0;
                        line << " " << format_number(100.0 * r.failure_rate(), 3) << " % |";
                    }
            if (!fails && all.sets > 0) {
                never.push_back(m);
                continue;
            }
            line << " " << (all.sets == 0 ? std::string("—") : failure_classes(all)) << " |\n";
            s << line.str();
        }
        if (!never.empty()) {
            s << "\nNever failed:";
            for (std::size_t i = 0; i < never.size(); ++i) s << (i ? ", " : " ") << never[i];
            s << ".\n";
        }
    }
    return s.str();
}

}  // namespace cagd::compare
