// Test helper: the cases of tests/reference/moments_reference.csv (the independent 60-digit
// mpmath oracle, moments_reference.py), indexed by case, node count and quantity.
#pragma once

#include <map>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "reference_table.hpp"

namespace fluidbed::test {

// values(case, n_nodes, quantity)[index]; moments are stored with n_nodes = 0.
class MomentReference {
 public:
  static const MomentReference& instance() {
    static const MomentReference reference;
    return reference;
  }

  const std::vector<double>& values(const std::string& name, int n_nodes, const std::string& quantity) const {
    const auto it = values_.find({name, n_nodes, quantity});
    if (it == values_.end())
      throw std::runtime_error("moments_reference.csv has no " + quantity + " for " + name + " N=" +
                               std::to_string(n_nodes));
    return it->second;
  }
  const std::vector<double>& moments(const std::string& name) const { return values(name, 0, "moment"); }
  bool has(const std::string& name, int n_nodes, const std::string& quantity) const {
    return values_.count({name, n_nodes, quantity}) == 1;
  }
  // Every case's moments m_0 … m_{L−1}, by case.
  std::map<std::string, std::vector<double>> moment_sets() const {
    std::map<std::string, std::vector<double>> out;
    for (const auto& entry : values_)
      if (std::get<2>(entry.first) == "moment") out.emplace(std::get<0>(entry.first), entry.second);
    return out;
  }
  // Every (case, node count) that has a rule (node rows), in order.
  std::vector<std::pair<std::string, int>> rules() const {
    std::vector<std::pair<std::string, int>> out;
    for (const auto& entry : values_)
      if (std::get<2>(entry.first) == "node") out.emplace_back(std::get<0>(entry.first), std::get<1>(entry.first));
    return out;
  }

 private:
  MomentReference() {
    const ReferenceTable table("moments_reference.csv");
    for (std::size_t row = 0; row < table.size(); ++row) {
      std::vector<double>& v =
          values_[{table.text(row, "case"), int(table.number(row, "n_nodes")), table.text(row, "quantity")}];
      const auto index = std::size_t(table.number(row, "index"));
      if (v.size() <= index) v.resize(index + 1);
      v[index] = table.number(row, "value");
    }
  }
  std::map<std::tuple<std::string, int, std::string>, std::vector<double>> values_;
};

}  // namespace fluidbed::test
