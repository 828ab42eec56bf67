// Google Benchmark reporter shared by the benchmarks: keeps the ns per cell of the fastest
// repetition of every benchmark (the least disturbed by other load) and prints tables of
// ns per cell with the ratio to a baseline measured in the same run (the ratio is what
// carries across machines).
#pragma once

#include <benchmark/benchmark.h>

#include <cstdio>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace fluidbed::bench {

class RatioReporter : public benchmark::ConsoleReporter {
 public:
  // Every benchmark processes `cells` cells per iteration.
  explicit RatioReporter(int cells) : cells_(cells) {}

  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& r : runs)
      if (r.run_type == Run::RT_Iteration) {
        const double ns = r.GetAdjustedRealTime() / benchmark::GetTimeUnitMultiplier(r.time_unit) * 1e9 / cells_;
        const auto [it, inserted] = ns_per_cell_.try_emplace(r.run_name.function_name, ns);
        if (!inserted && ns < it->second) it->second = ns;
      }
  }

  // One line per row that was run; per column, the ns per cell of the benchmark "column/row"
  // and its ratio to the benchmark named baseline(row) (blank where either was not run).
  void print_table(const std::string& row_title, const std::vector<std::string>& rows,
                   const std::vector<std::string>& columns,
                   const std::function<std::string(const std::string& row)>& baseline,
                   const std::string& baseline_description) const {
    std::vector<Column> with_baselines;
    for (const std::string& column : columns) with_baselines.push_back({column, baseline});
    print_table(row_title, rows, with_baselines, baseline_description);
  }

  // A column whose ratios have their own baseline (e.g. each row's own value for its derivatives).
  struct Column {
    std::string name;
    std::function<std::string(const std::string& row)> baseline;
  };

  // The same with a baseline per column.
  void print_table(const std::string& row_title, const std::vector<std::string>& rows,
                   const std::vector<Column>& columns, const std::string& baseline_description) const {
    std::printf("\n%-20s", row_title.c_str());
    for (const Column& column : columns) std::printf(" %18s %7s", (column.name + " ns").c_str(), "ratio");
    std::printf("\n");
    for (const std::string& row : rows) {
      bool run = false;
      for (const Column& column : columns) run = run || ns_per_cell_.count(column.name + "/" + row) > 0;
      if (!run) continue;
      std::printf("%-20s", row.c_str());
      for (const Column& column : columns) {
        const auto ns = ns_per_cell_.find(column.name + "/" + row);
        const auto base = ns_per_cell_.find(column.baseline(row));
        if (ns == ns_per_cell_.end())
          std::printf(" %18s %7s", "", "");
        else if (base == ns_per_cell_.end())
          std::printf(" %18.2f %7s", ns->second, "");
        else
          std::printf(" %18.2f %7.3f", ns->second, ns->second / base->second);
      }
      std::printf("\n");
    }
    std::printf("(ns per cell, fastest repetition; ratios are to %s in this run)\n", baseline_description.c_str());
  }

 private:
  int cells_;
  std::map<std::string, double> ns_per_cell_;
};

}  // namespace fluidbed::bench
