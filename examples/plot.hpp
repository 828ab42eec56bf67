// The gnuplot plotting shared by the example programs.
//
// An example collects its curves in Panels and calls plot::render(directory, name, panels),
// which writes <directory>/<name>.dat (one data block per curve), <directory>/<name>.gp (the
// gnuplot script) and runs gnuplot to draw <directory>/<name>.png (pngcairo, UTF-8 labels,
// enhanced text: x_{sub}, x^{sup}). Several panels are laid out side by side (multiplot).
//
// Every example takes the output directory as its only, optional, argument
// (plot::output_directory). Without it, as when ctest runs the examples, nothing is written
// and nothing is plotted: the examples check their numbers without gnuplot. With it, a
// missing gnuplot leaves the .dat and .gp files and a note, never a failure.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <deque>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace plot {

struct Series {
  std::string title;                 // legend entry; empty: no entry
  std::string style = "lines lw 2";  // what follows gnuplot's `with`
  std::string axes = "x1y1";         // "x1y2" for the right-hand axis
  std::vector<double> x, y;

  Series(std::string title_, std::string style_) : title(std::move(title_)), style(std::move(style_)) {}

  Series& point(double px, double py) {
    x.push_back(px);
    y.push_back(py);
    return *this;
  }
  // Ends a line here: gnuplot leaves a gap (a curve interrupted where a law has no solution).
  Series& gap() { return point(nan_marker, nan_marker); }

  static constexpr double nan_marker = 1e308;  // written as a blank line
};

struct Panel {
  Panel(std::string title_, std::string xlabel_, std::string ylabel_)
      : title(std::move(title_)), xlabel(std::move(xlabel_)), ylabel(std::move(ylabel_)) {}

  std::string title, xlabel, ylabel, y2label;
  bool log_x = false, log_y = false;
  std::string xrange, yrange, y2range;  // gnuplot ranges, e.g. "[1e-3:1e5]"; empty: automatic
  std::string key = "top right";        // gnuplot `set key` arguments
  std::vector<std::string> commands;    // further gnuplot commands (set arrow, set label, ...)
  std::deque<Series> series;            // a deque: the reference add() returns stays valid after later adds

  Series& add(std::string legend, std::string style = "lines lw 2") {
    series.emplace_back(std::move(legend), std::move(style));
    return series.back();
  }
};

// A gnuplot range "[low:high]".
inline std::string range(double low, double high) {
  char text[64];
  std::snprintf(text, sizeof text, "[%.6g:%.6g]", low, high);
  return text;
}

// A gnuplot string literal: single-quoted, '' for a quote.
inline std::string gnuplot_string(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("''") : std::string(1, c);
  return out + "'";
}

// A label for enhanced text: quoted, with '&' (an enhanced-text operator) printed as itself.
// Sub- and superscripts (x_{ab}, x^{2}) keep their meaning.
inline std::string label(const std::string& text) {
  std::string escaped;
  for (char c : text) escaped += c == '&' ? std::string("\\&") : std::string(1, c);
  return gnuplot_string(escaped);
}

// A shell word: single-quoted, '\'' for a quote.
inline std::string shell_quoted(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

inline bool gnuplot_available() { return std::system("command -v gnuplot >/dev/null 2>&1") == 0; }

// argv[1] when given (created if missing), else nothing: no plots.
inline std::optional<std::string> output_directory(int argc, char** argv) {
  if (argc < 2) return std::nullopt;
  const std::string directory = argv[1];
  if (std::system(("mkdir -p " + shell_quoted(directory)).c_str()) != 0) return std::nullopt;
  return directory;
}

// Writes the data and the script of `panels` (laid out in one row, each width × height pixels,
// under `page_title` if there are several) and runs gnuplot. Returns the PNG's path, or an empty
// string after printing why there is none.
inline std::string render(const std::string& directory, const std::string& name, const std::vector<Panel>& panels,
                          int width = 900, int height = 600, const std::string& page_title = "") {
  const std::string data = directory + "/" + name + ".dat", script = directory + "/" + name + ".gp",
                    png = directory + "/" + name + ".png";
  std::FILE* out = std::fopen(data.c_str(), "w");
  if (!out) {
    std::printf("cannot write %s: no plot\n", data.c_str());
    return "";
  }
  int block = 0;
  for (const Panel& panel : panels)
    for (const Series& s : panel.series) {
      std::fprintf(out, "# block %d: %s\n", block++, s.title.c_str());
      // One blank line breaks the curve; two would end the block, so gaps are merged and
      // never written first or last.
      bool written = false, gap = false;
      for (std::size_t i = 0; i < s.x.size(); ++i) {
        if (s.x[i] == Series::nan_marker) {
          gap = written;
          continue;
        }
        if (gap) std::fprintf(out, "\n");
        std::fprintf(out, "%.10g %.10g\n", s.x[i], s.y[i]);
        written = true;
        gap = false;
      }
      if (!written) std::fprintf(out, "nan nan\n");  // an empty block still counts as a block
      std::fprintf(out, "\n\n");
    }
  std::fclose(out);

  out = std::fopen(script.c_str(), "w");
  if (!out) {
    std::printf("cannot write %s: no plot\n", script.c_str());
    return "";
  }
  const int columns = int(panels.size());
  std::fprintf(out, "set encoding utf8\nset terminal pngcairo enhanced size %d,%d font ',11'\nset output %s\n",
               width * columns, height, gnuplot_string(png).c_str());
  if (columns > 1)
    std::fprintf(out, "set multiplot layout 1,%d%s\n", columns,
                 page_title.empty() ? "" : (" title " + label(page_title) + " font ',13'").c_str());
  block = 0;
  for (const Panel& panel : panels) {
    std::fprintf(out, "reset\nset grid\nset title %s\nset xlabel %s\nset ylabel %s\nset key %s\n",
                 label(panel.title).c_str(), label(panel.xlabel).c_str(), label(panel.ylabel).c_str(),
                 panel.key.c_str());
    bool right_axis = false;
    for (const Series& s : panel.series) right_axis = right_axis || s.axes == "x1y2";
    if (right_axis) {
      std::fprintf(out, "set y2label %s\nset y2tics\nset ytics nomirror\n", label(panel.y2label).c_str());
      if (!panel.y2range.empty()) std::fprintf(out, "set y2range %s\n", panel.y2range.c_str());
    }
    if (panel.log_x) std::fprintf(out, "set logscale x\nset format x '10^{%%L}'\n");
    if (panel.log_y) std::fprintf(out, "set logscale y\nset format y '10^{%%L}'\n");
    if (!panel.xrange.empty()) std::fprintf(out, "set xrange %s\n", panel.xrange.c_str());
    if (!panel.yrange.empty()) std::fprintf(out, "set yrange %s\n", panel.yrange.c_str());
    for (const std::string& command : panel.commands) std::fprintf(out, "%s\n", command.c_str());
    std::fprintf(out, "plot ");
    for (std::size_t i = 0; i < panel.series.size(); ++i, ++block) {
      const Series& s = panel.series[i];
      std::fprintf(out, "%s%s index %d using 1:2 axes %s with %s %s", i ? ", \\\n     " : "",
                   gnuplot_string(data).c_str(), block, s.axes.c_str(), s.style.c_str(),
                   s.title.empty() ? "notitle" : ("title " + label(s.title)).c_str());
    }
    std::fprintf(out, "\n");
  }
  if (columns > 1) std::fprintf(out, "unset multiplot\n");
  std::fclose(out);

  if (!gnuplot_available()) {
    std::printf("gnuplot not found: %s and %s written, no PNG\n", data.c_str(), script.c_str());
    return "";
  }
  if (std::system(("gnuplot " + shell_quoted(script)).c_str()) != 0) {
    std::printf("gnuplot failed on %s: no PNG\n", script.c_str());
    return "";
  }
  return png;
}

}  // namespace plot
