#include "cli/curve_output.hpp"

#include <string>
#include <vector>

namespace cagd::cli {

void write_curve(const Curve& c, int samples_per_span, OutputFile& out, const std::string& parameter_column) {
    const std::vector<double> br = c.breakpoints();
    require_output_rows(static_cast<double>(samples_per_span) * static_cast<double>(br.size() - 1) + 1, "--samples " + std::to_string(samples_per_span));
    const int d = c.dimension();
    const char* names = "xyz";
    std::vector<std::string> header{parameter_column};
    for (const char* prefix : {"", "d", "dd"})
        for (int k = 0; k < d; ++k) header.push_back(std::string(prefix) + names[k]);
    CsvOutput w(out, header);
    for (std::size_t s = 0; s + 1 < br.size(); ++s)
        for (int j = 0; j < samples_per_span + (s + 2 == br.size() ? 1 : 0); ++j) {
            const double u = br[s] + (br[s + 1] - br[s]) * j / samples_per_span;
            const Eigen::MatrixXd J = c.jet(u, 2);
            std::vector<double> row{u};
            for (int k = 0; k < 3; ++k)
                for (int i = 0; i < d; ++i) row.push_back(J(k, i));
            w.row(row, 15);
        }
}

}  // namespace cagd::cli
