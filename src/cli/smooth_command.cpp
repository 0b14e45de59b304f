// `cagd smooth (--lambda L | --lambda-file F) [--form yx|parametric] [--samples N] --in P.csv
// --out C.csv`: the elastic line of hosaka section 6 (eq 50–52) on y(x) data or on a parametric
// point list.
#include <memory>

#include "cagd/core/csv.hpp"
#include "cagd/core/errors.hpp"
#include "cagd/core/point_csv.hpp"
#include "cagd/smoothing/elastic_line.hpp"
#include "cli/commands.hpp"
#include "cli/output.hpp"

namespace cagd::cli {

namespace {

enum class SmoothForm { yx, parametric };

struct SmoothArgs {
    std::string in, out, lambda_file;
    SmoothForm form = SmoothForm::yx;
    double lambda = 0.0;
    int samples = 20;
    bool lambda_given = false;
};

int run_smooth(const SmoothArgs& a) {
    const char* who = "cagd smooth";
    if (a.lambda_given == !a.lambda_file.empty()) fail_input(who, "give exactly one of --lambda and --lambda-file");
    const PointList points = read_data_points(a.in);
    std::vector<double> lambda{a.lambda};
    if (!a.lambda_file.empty()) lambda = read_values_csv(a.lambda_file);
    require_output_rows(static_cast<double>(a.samples) * static_cast<double>(points.rows()) + 1,
                        "--samples " + std::to_string(a.samples));
    OutputFile out(a.out);
    const char* names = "xyz";
    if (a.form == SmoothForm::yx) {  // rows x, y[, z]: y(x) (and z(x)) smoothed
        if (points.cols() < 2) fail_input(who, "--form yx needs rows x,y or x,y,z");
        const std::vector<double> x(points.col(0).data(), points.col(0).data() + points.rows());
        const smoothing::ElasticLine line = smoothing::elastic_line(x, points.rightCols(points.cols() - 1), lambda);
        std::vector<std::string> header{"x"};
        for (const char* prefix : {"", "d", "dd"})
            for (Eigen::Index k = 1; k < points.cols(); ++k) header.push_back(std::string(prefix) + names[k]);
        CsvOutput w(out, header);
        for (std::size_t i = 0; i + 1 < x.size(); ++i)
            for (int k = 0; k < a.samples || (i + 2 == x.size() && k == a.samples); ++k) {
                const double u = double(k) / a.samples;
                std::vector<double> row{x[i] + u * (x[i + 1] - x[i])};
                for (int order = 0; order <= 2; ++order) {
                    const Eigen::RowVectorXd v = line.curve.evaluate_in(static_cast<int>(i), u, order);
                    row.insert(row.end(), v.data(), v.data() + v.size());
                }
                w.row(row, 15);
            }
        out.commit();
        return 0;
    }
    // parametric: x(t), y(t)[, z(t)] over the chord-length parameter
    const smoothing::ElasticLine line = smoothing::elastic_line_parametric(points, lambda);
    std::vector<std::string> header{"t"};
    for (Eigen::Index k = 0; k < points.cols(); ++k) header.push_back(std::string(1, names[k]));
    CsvOutput w(out, header);
    for (std::size_t i = 0; i + 1 < line.x().size(); ++i)
        for (int k = 0; k < a.samples || (i + 2 == line.x().size() && k == a.samples); ++k) {
            const double u = double(k) / a.samples;
            std::vector<double> row{line.x()[i] + u * (line.x()[i + 1] - line.x()[i])};
            const Eigen::RowVectorXd v = line.curve.evaluate_in(static_cast<int>(i), u);
            row.insert(row.end(), v.data(), v.data() + v.size());
            w.row(row, 15);
        }
    out.commit();
    return 0;
}

}  // namespace

Command add_smooth_command(CLI::App& app) {
    auto a = std::make_shared<SmoothArgs>();
    CLI::App* c = app.add_subcommand(
        "smooth", "Elastic-line smoothing (hosaka section 6, eq 50-52): y(x) data or a parametric point list");
    CLI::Option* lambda =
        c->add_option("--lambda", a->lambda, "lambda = EI/k for every point (>= 0; 0 interpolates; units length^3)");
    c->add_option("--lambda-file", a->lambda_file, "one lambda per data point, one per line");
    add_enum_option(c, "--form", a->form, {{"yx", SmoothForm::yx}, {"parametric", SmoothForm::parametric}},
                    "yx: rows x,y[,z], x strictly increasing | parametric: 2-D/3-D points, chord parameter");
    c->add_option("--samples", a->samples, "samples per interval")->check(CLI::Range(1, 100000));
    c->add_option("--in", a->in, "data CSV; - for stdin")->required();
    c->add_option("--out", a->out, "smoothed curve CSV (yx: x, values, first and second derivatives); - for stdout")
        ->required();
    return {c, [a, lambda] {
                a->lambda_given = lambda->count() > 0;
                return run_smooth(*a);
            }};
}

}  // namespace cagd::cli
