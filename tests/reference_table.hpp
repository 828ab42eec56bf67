// Test helper: reads the CSV tables written by the independent generators in
// tests/reference/ (Python + mpmath). Columns are addressed by header name.
#pragma once

#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace fluidbed::test {

class ReferenceTable {
 public:
  explicit ReferenceTable(const std::string& file_name) {
    const std::string path = std::string(FLUIDBED_REFERENCE_DIR) + "/" + file_name;
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot open reference table " + path);
    std::string line;
    std::getline(in, line);
    header_ = split(line);
    for (std::size_t i = 0; i < header_.size(); ++i) column_[header_[i]] = i;
    while (std::getline(in, line))
      if (!line.empty() && line[0] != '#') rows_.push_back(split(line));
  }

  std::size_t size() const { return rows_.size(); }
  const std::string& text(std::size_t row, const std::string& column) const { return rows_.at(row).at(index(column)); }
  double number(std::size_t row, const std::string& column) const { return std::stod(text(row, column)); }

 private:
  static std::vector<std::string> split(const std::string& line) {
    std::vector<std::string> cells;
    std::stringstream stream(line);
    std::string cell;
    while (std::getline(stream, cell, ',')) cells.push_back(cell);
    if (!line.empty() && line.back() == ',') cells.emplace_back();  // a trailing empty field
    return cells;
  }
  std::size_t index(const std::string& column) const {
    const auto it = column_.find(column);
    if (it == column_.end()) throw std::runtime_error("no column " + column);
    return it->second;
  }

  std::vector<std::string> header_;
  std::map<std::string, std::size_t> column_;
  std::vector<std::vector<std::string>> rows_;
};

}  // namespace fluidbed::test
