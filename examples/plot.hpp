// The gnuplot plotting shared by the example programs.
//
// An example collects its curves in Panels and calls plot::render(directory, name, panels, page),
// which writes <directory>/<name>.dat (one data block per curve), <directory>/<name>.gp (the
// gnuplot script) and runs gnuplot to draw <directory>/<name>.png (pngcairo, UTF-8 labels,
// enhanced text: x_{sub}, x^{sup}). Several panels are laid out in a grid (multiplot): one row
// unless the Page says how many columns. The script reads its .dat and writes its PNG beside
// itself, wherever it is run from: `gnuplot /path/to/<name>.gp` redraws the picture.
//
// Curves that a reader must tell apart take plot::look(i): colour, point type and dash pattern
// all change with i, so that they stay distinguishable in greyscale.
//
// Every example takes the output directory as its only, optional, argument
// (plot::output_directory). Without it, as when ctest runs the examples, nothing is written
// and nothing is plotted: the examples check their numbers without gnuplot. With it, a
// missing gnuplot leaves the .dat and .gp files and a message, never a failure.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <deque>
#include <filesystem>
#include <iterator>
#include <optional>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

namespace plot {

// How curve number `index` of a family is drawn: colour (Okabe & Ito's palette, yellow left out
// as unreadable on white), point type and dash pattern.
struct Look {
  std::string colour;  // "#rrggbb"
  int point;           // gnuplot point type (pngcairo: 4-15 squares, circles, triangles, diamonds, pentagons)
  std::string dash;    // gnuplot dash type

  // The `with` clause of a line in this look (or in its colour with another dash pattern).
  std::string line(double width = 2, const std::string& other_dash = "") const {
    char text[96];
    std::snprintf(text, sizeof text, "lines lw %g dt %s lc rgb '%s'", width,
                  (other_dash.empty() ? dash : other_dash).c_str(), colour.c_str());
    return text;
  }
  // The point options of a marker in this look.
  std::string marker(double size = 1.2) const {
    char text[64];
    std::snprintf(text, sizeof text, "pt %d ps %g lc rgb '%s'", point, size, colour.c_str());
    return text;
  }
};

inline Look look(int index) {
  static const char* const colours[] = {"#0072b2", "#d55e00", "#009e73", "#cc79a7",
                                        "#e69f00", "#56b4e9", "#000000", "#9400d3"};
  static const int points[] = {7, 5, 9, 13, 11, 6, 4, 8, 12, 10, 15, 14};
  static const char* const dashes[] = {"1", "(10,4)", "(3,3)", "(10,3,2,3)", "(18,5)", "(5,5)", "(14,4,2,4,2,4)"};
  const auto pick = [index](const auto& list) { return list[std::size_t(index) % std::size(list)]; };
  return {pick(colours), pick(points), pick(dashes)};
}

struct Series {
  std::string title;                 // legend entry; empty: no entry
  std::string style = "lines lw 2";  // what follows gnuplot's `with`
  std::string axes = "x1y1";         // "x1y2" for the right-hand axis
  // Markers: gnuplot point options (Look::marker) drawn on every marker_every-th sample from
  // sample marker_first (staggered between curves, so that coinciding curves keep visible
  // markers); the legend then shows line and marker. With markers, style is a "lines ..." style.
  std::string marker;
  int marker_every = 0, marker_first = 0;
  bool legend_only = false;  // a legend entry without data (gnuplot's keyentry)
  std::vector<double> x, y;

  Series(std::string title_, std::string style_) : title(std::move(title_)), style(std::move(style_)) {}

  Series& point(double px, double py) {
    x.push_back(px);
    y.push_back(py);
    return *this;
  }
  // Ends a line here: gnuplot leaves a gap (a curve interrupted where a law has no solution).
  Series& gap() { return point(nan_marker, nan_marker); }
  Series& with_markers(std::string point_options, int every, int first = 0) {
    marker = std::move(point_options);
    marker_every = every;
    marker_first = first;
    return *this;
  }

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
  // A curve in look `l`: its line, and a marker every `every` samples from sample `first`.
  Series& add(std::string legend, const Look& l, int every, int first, double width = 2) {
    return add(std::move(legend), l.line(width)).with_markers(l.marker(), every, first);
  }
  // A legend entry only, e.g. to explain a line style shared by several curves.
  Series& add_legend(std::string legend, std::string style) {
    Series& s = add(std::move(legend), std::move(style));
    s.legend_only = true;
    return s;
  }
};

// How the panels of one picture are laid out.
struct Page {
  std::string title;  // above the panels, when there are several
  int columns = 0;    // panels per row; 0: all in one row
  int panel_width = 900, panel_height = 600;
};

// A gnuplot range "[low:high]".
inline std::string range(double low, double high) {
  char text[64];
  std::snprintf(text, sizeof text, "[%.6g:%.6g]", low, high);
  return text;
}

// A gnuplot string expression: single-quoted, '' for a quote; a newline in `text` becomes a
// line break ('...'."\n".'...').
inline std::string gnuplot_string(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("''") : c == '\n' ? std::string("'.\"\\n\".'") : std::string(1, c);
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
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (!std::filesystem::is_directory(directory)) {
    std::printf("cannot create the directory %s: no plots\n", directory.c_str());
    return std::nullopt;
  }
  return directory;
}

namespace detail {

// Writes one data block: x y per line, a blank line for each run of gaps (two would end the
// block, so gaps are merged and never written first or last), then two blank lines.
inline void write_block(std::FILE* out, const std::string& title, int block, const std::vector<double>& x,
                        const std::vector<double>& y, int every = 1, int first = 0) {
  std::fprintf(out, "# block %d: %s\n", block, title.c_str());
  bool written = false, gap = false;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (x[i] == Series::nan_marker) {
      gap = written;
      continue;
    }
    if ((int(i) - first) % every != 0) continue;
    if (gap) std::fprintf(out, "\n");
    std::fprintf(out, "%.10g %.10g\n", x[i], y[i]);
    written = true;
    gap = false;
  }
  if (!written) std::fprintf(out, "nan nan\n");  // an empty block still counts as a block
  std::fprintf(out, "\n\n");
}

}  // namespace detail

// Writes the data and the script of `panels`, laid out as `page` says, and runs gnuplot.
// Returns the PNG's path, or an empty string after printing why there is none.
inline std::string render(const std::string& directory, const std::string& name, const std::vector<Panel>& panels,
                          const Page& page = {}) {
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
      if (s.legend_only) continue;
      detail::write_block(out, s.title, block++, s.x, s.y);
      if (!s.marker.empty()) detail::write_block(out, s.title + " (markers)", block++, s.x, s.y, s.marker_every, s.marker_first);
    }
  std::fclose(out);

  out = std::fopen(script.c_str(), "w");
  if (!out) {
    std::printf("cannot write %s: no plot\n", script.c_str());
    return "";
  }
  const int count = int(panels.size());
  const int columns = page.columns > 0 && page.columns < count ? page.columns : count;
  const int rows = (count + columns - 1) / columns;
  std::error_code error;
  const std::string absolute_directory = std::filesystem::absolute(directory, error).lexically_normal().string();
  // gnuplot sets ARG0 to the path it was given for the script: the data and the PNG are taken
  // relative to it, so that the script runs from any directory (and from a copied directory).
  std::fprintf(out,
               "# Draws %s.png from %s.dat, both beside this script, from any working directory:\n"
               "#   gnuplot /path/to/%s.gp\n"
               "script = %s\n"
               "here = (strlen(ARG0) >= strlen(script) && ARG0[strlen(ARG0) - strlen(script) + 1:] eq script) ? "
               "ARG0[1:strlen(ARG0) - strlen(script)] : %s\n"
               "data = here.%s\n"
               "set encoding utf8\nset terminal pngcairo enhanced size %d,%d font ',11'\nset output here.%s\n",
               name.c_str(), name.c_str(), name.c_str(), gnuplot_string(name + ".gp").c_str(),
               gnuplot_string(absolute_directory + "/").c_str(), gnuplot_string(name + ".dat").c_str(),
               page.panel_width * columns, page.panel_height * rows, gnuplot_string(name + ".png").c_str());
  if (count > 1)
    std::fprintf(out, "set multiplot layout %d,%d%s\n", rows, columns,
                 page.title.empty() ? "" : (" title " + label(page.title) + " font ',13'").c_str());
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
    const char* separator = "";
    const auto element = [&](const std::string& text) {
      std::fprintf(out, "%s%s", separator, text.c_str());
      separator = ", \\\n     ";
    };
    const auto title_of = [](const Series& s) { return s.title.empty() ? std::string("notitle") : "title " + label(s.title); };
    for (const Series& s : panel.series) {
      if (s.legend_only) {
        element("keyentry with " + s.style + " " + title_of(s));
        continue;
      }
      const std::string source = "data index " + std::to_string(block++) + " using 1:2 axes " + s.axes;
      if (s.marker.empty()) {
        element(source + " with " + s.style + " " + title_of(s));
        continue;
      }
      element(source + " with " + s.style + " notitle");
      element("data index " + std::to_string(block++) + " using 1:2 axes " + s.axes + " with points " + s.marker +
              " notitle");
      // "lines <options>" and the marker's point type and size, as one legend sample.
      if (!s.title.empty())
        element("keyentry with linespoints" + s.style.substr(5) + " " + s.marker.substr(0, s.marker.find(" lc ")) +
                " " + title_of(s));
    }
    std::fprintf(out, "\n");
  }
  if (count > 1) std::fprintf(out, "unset multiplot\n");
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
