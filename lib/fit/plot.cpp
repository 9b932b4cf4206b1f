#include "fit/plot.hpp"

#include "core/errors.hpp"
#include "io/csv.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <sys/wait.h>
#include <unistd.h>

namespace cmp::fit {

namespace fs = std::filesystem;

namespace {

// gnuplot single-quoted string: a quote is doubled.
std::string quoted(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("''") : std::string(1, c);
  return q + "'";
}

// POSIX shell single-quoted word.
std::string shell_quoted(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

int run(const std::string& command) {
  const int status = std::system(command.c_str());
  return status == -1 ? -1 : (WIFEXITED(status) ? WEXITSTATUS(status) : -1);
}

}  // namespace

std::string png_terminal() {
  static std::once_flag once;
  static std::string terminal;
  std::call_once(once, [] {
    if (run("gnuplot -e 'set terminal pngcairo' </dev/null >/dev/null 2>&1") == 0) terminal = "pngcairo";
    else if (run("gnuplot -e 'set terminal png' </dev/null >/dev/null 2>&1") == 0) terminal = "png";
  });
  if (terminal.empty())
    throw ComputationError("--plot needs gnuplot with the pngcairo or png terminal (Debian: gnuplot-nox)");
  return terminal;
}

std::string render_plot(const std::string& path, const PlotSpec& spec) {
  const std::string terminal = png_terminal();
  const fs::path target(path);
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::string templ = (dir / ("." + target.filename().string() + ".tmp.XXXXXX")).string();
  std::vector<char> buf(templ.begin(), templ.end());
  buf.push_back('\0');
  if (!::mkdtemp(buf.data())) throw InputError(path, 0, "cannot write the plot here (folder missing or read-only)");
  const fs::path work(buf.data());
  struct Cleanup {
    fs::path p;
    ~Cleanup() { std::error_code ec; fs::remove_all(p, ec); }
  } cleanup{work};

  {
    std::ofstream data(work / "data.dat");
    for (std::size_t i = 0; i < spec.x.size(); ++i)
      data << io::format_number(spec.x[i]) << ' ' << io::format_number(spec.y[i]) << '\n';
    std::ofstream curve(work / "curve.dat");
    const int samples = 400;
    for (int s = 0; s <= samples; ++s) {
      const double x = spec.curve_from + (spec.curve_to - spec.curve_from) * s / samples;
      curve << io::format_number(x);
      for (const auto& c : spec.curves) {
        const double f = c.model->value(x, c.p.data());
        curve << ' ' << (std::isfinite(f) && (!spec.log_y || f > 0) ? io::format_number(f) : std::string("NaN"));
      }
      curve << '\n';
    }
  }
  const fs::path png = work / "plot.png";
  {
    std::ofstream gp(work / "plot.gp");
    gp << "set terminal " << terminal << " size 900,720" << (terminal == "pngcairo" ? " enhanced font ',12'" : "")
       << "\nset output " << quoted(png.string()) << "\nset xlabel " << quoted(spec.x_label) << " noenhanced"
       << "\nset ylabel " << quoted(spec.y_label) << " noenhanced" << "\nset title " << quoted(spec.title) << " noenhanced"
       << "\nset key below left Left reverse noenhanced\nset grid\nset datafile missing 'NaN'\n";
    if (spec.log_y) gp << "set logscale y\nset format y '10^{%L}'\n";
    else gp << "set offsets 0, 0, graph 0.04, graph 0.04\n";  // points on 0 and 1 stay visible
    gp << "plot " << quoted((work / "data.dat").string()) << " using 1:2 with points pt 7 ps 0.7 lc rgb '#1f77b4' title 'data'";
    const char* colours[] = {"#d62728", "#2ca02c", "#ff7f0e"};
    for (std::size_t c = 0; c < spec.curves.size(); ++c)
      gp << ", " << quoted((work / "curve.dat").string()) << " using 1:" << c + 2 << " with lines lw 2 dt "
         << (c == 0 ? 1 : 2) << " lc rgb '" << colours[c % 3] << "' title " << quoted(spec.curves[c].title);
    gp << "\n";
  }
  const std::string command =
      fmt::format("gnuplot {} >{} 2>&1", shell_quoted((work / "plot.gp").string()),
                  shell_quoted((work / "gnuplot.log").string()));
  if (run(command) != 0 || !fs::exists(png)) {
    std::ifstream log(work / "gnuplot.log");
    std::string line, all;
    while (std::getline(log, line)) all += (all.empty() ? "" : " | ") + line;
    throw ComputationError("gnuplot failed: " + all);
  }
  // Keep the PNG as a hidden file beside the target until commit.
  const std::string temp = (dir / ("." + target.filename().string() + ".tmp.png")).string();
  std::error_code ec;
  fs::rename(png, temp, ec);
  if (ec) throw InputError(path, 0, "cannot write the plot here: " + ec.message());
  return temp;
}

void commit_plot(const std::string& temp, const std::string& path) {
  std::error_code ec;
  fs::rename(temp, path, ec);
  if (ec) throw InputError(path, 0, "cannot write the plot: " + ec.message());
}

void discard_plot(const std::string& temp) {
  std::error_code ec;
  fs::remove(temp, ec);
}

}  // namespace cmp::fit
