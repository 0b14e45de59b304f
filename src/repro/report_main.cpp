// cagd_report [ROOT]: writes ROOT/results/claims.csv and ROOT/results/REPORT.md.
// Exit 1 if any claim or validation failed.
#include <iostream>

#include "repro/report.hpp"

int main(int argc, char** argv) {
    const std::string root = argc > 1 ? argv[1] : ".";
    try {
        const int failed = cagd::repro::write_report(root);
        std::cout << "report: results/REPORT.md, results/claims.csv (" << failed << " failed)\n";
        return failed > 0 ? 1 : 0;
    } catch (const std::exception& e) {
        std::cerr << "cagd_report: " << e.what() << "\n";
        return 2;
    }
}
