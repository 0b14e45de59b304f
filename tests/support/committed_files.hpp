#pragma once
// Committed files of the source tree (CAGD_SOURCE_DIR), for tests that check prose against results:
// a text file whole, and a CSV as rows of fields by column name.
#include <fstream>
#include <iterator>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "cagd/core/csv.hpp"

namespace cagd::test {

/// The file `relative` (to the source tree) as text; std::runtime_error naming it when unreadable.
inline std::string committed_text(const std::string& relative) {
    std::ifstream in(std::string(CAGD_SOURCE_DIR) + "/" + relative);
    if (!in) throw std::runtime_error("cannot read " + relative);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// The rows of the CSV file `relative`, each a map from its header's column names to the fields.
inline std::vector<std::map<std::string, std::string>> committed_csv(const std::string& relative) {
    std::ifstream in(std::string(CAGD_SOURCE_DIR) + "/" + relative);
    if (!in) throw std::runtime_error("cannot read " + relative);
    std::string line;
    std::getline(in, line);
    const std::vector<std::string> header = split_csv_line(line);
    std::vector<std::map<std::string, std::string>> rows;
    while (std::getline(in, line)) {
        const std::vector<std::string> fields = split_csv_line(line);
        if (fields.size() != header.size())
            throw std::runtime_error(relative + ": a row's fields differ from the header");
        std::map<std::string, std::string>& row = rows.emplace_back();
        for (std::size_t i = 0; i < header.size(); ++i) row[header[i]] = fields[i];
    }
    return rows;
}

}  // namespace cagd::test
