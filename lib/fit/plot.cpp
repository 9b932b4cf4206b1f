#include "fit/plot.hpp"

#include "core/errors.hpp"
#include "io/csv.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <mutex>
#include <memory>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace cmp::fit {

namespace {

// gnuplot single-quoted string: a quote is doubled; a line break becomes gnuplot's "\n".
std::string quoted(const std::string& s) {
  std::string q = "'";
  for (char c : s) {
    if (c == '\'') q += "''";
    else if (c == '\n') q += "'.\"\\n\".'";
    else q += c;
  }
  return q + "'";
}

struct FileCloser {
  void operator()(std::FILE* f) const { if (f) std::fclose(f); }
};
using File = std::unique_ptr<std::FILE, FileCloser>;

// What a finished gnuplot run gave.
struct Run {
  int status = 0;          // waitpid status
  std::string out, err;    // its standard output and error
};

std::string read_all(std::FILE* f) {
  std::string s;
  std::rewind(f);
  char buf[4096];
  std::size_t got;
  while ((got = std::fread(buf, 1, sizeof buf, f)) > 0) s.append(buf, got);
  return s;
}

// Runs gnuplot with args, script on its stdin; stderr into an anonymous file (no deadlock
// between two pipes), stdout read through a pipe until EOF, then waitpid.
Run run_gnuplot(const std::vector<std::string>& args, const std::string& script) {
  File in(std::tmpfile()), err(std::tmpfile());
  if (!in || !err) throw ComputationError(std::string("cannot run gnuplot: ") + std::strerror(errno));
  std::fwrite(script.data(), 1, script.size(), in.get());
  std::fflush(in.get());
  std::rewind(in.get());
  int out[2];
  if (::pipe(out) != 0) throw ComputationError(std::string("cannot run gnuplot: ") + std::strerror(errno));
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, fileno(in.get()), 0);
  posix_spawn_file_actions_adddup2(&actions, out[1], 1);
  posix_spawn_file_actions_adddup2(&actions, fileno(err.get()), 2);
  posix_spawn_file_actions_addclose(&actions, out[0]);
  std::vector<char*> argv;
  std::vector<std::string> owned{"gnuplot"};
  owned.insert(owned.end(), args.begin(), args.end());
  for (auto& a : owned) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int spawned = ::posix_spawnp(&pid, "gnuplot", &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(out[1]);
  if (spawned != 0) {
    ::close(out[0]);
    throw ComputationError(fmt::format("--plot needs gnuplot (Debian: gnuplot-nox): {}", std::strerror(spawned)));
  }
  Run r;
  char buf[65536];
  for (;;) {
    const ssize_t got = ::read(out[0], buf, sizeof buf);
    if (got > 0) r.out.append(buf, static_cast<std::size_t>(got));
    else if (got == 0 || errno != EINTR) break;
  }
  ::close(out[0]);
  while (::waitpid(pid, &r.status, 0) < 0 && errno == EINTR) {
  }
  std::fflush(err.get());
  r.err = read_all(err.get());
  return r;
}

bool succeeded(const Run& r) { return WIFEXITED(r.status) && WEXITSTATUS(r.status) == 0; }

// gnuplot's messages on one line (the last few hundred characters).
std::string messages(const std::string& err) {
  std::string s;
  for (char c : err) s += c == '\n' ? std::string(" | ") : std::string(1, c);
  while (!s.empty() && (s.back() == ' ' || s.back() == '|')) s.pop_back();
  return s.size() > 400 ? "..." + s.substr(s.size() - 400) : s;
}

std::string png_terminal() {
  static std::once_flag once;
  static std::string terminal;
  std::call_once(once, [] {
    terminal = succeeded(run_gnuplot({"-e", "set terminal pngcairo"}, "")) ? "pngcairo" : "png";
  });
  return terminal;
}

const char* kPalette[] = {"#0072b2", "#d55e00", "#009e73", "#cc79a7", "#e69f00", "#56b4e9", "#000000", "#f0e442"};
constexpr int kColours = 8;

std::string number(double v) { return std::isfinite(v) ? io::format_number(v) : std::string("NaN"); }

}  // namespace

std::optional<PlotFormat> plot_format(const std::string& path) {
  const auto dot = path.find_last_of('.');
  if (dot == std::string::npos || path.find('/', dot) != std::string::npos) return std::nullopt;
  std::string ext = path.substr(dot + 1);
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext == "png") return PlotFormat::Png;
  if (ext == "svg") return PlotFormat::Svg;
  if (ext == "pdf") return PlotFormat::Pdf;
  return std::nullopt;
}

std::string enhanced_literal(const std::string& text) {
  std::string s;
  for (char c : text) {
    if (std::strchr("_^@&~{}", c)) s += '\\';
    s += c;
  }
  return s;
}

std::string symbol(const std::string& name) {
  static const std::map<std::string, std::string> symbols{
      {"phi_c", "{/Symbol f}_c"}, {"phi_c_star", "{/Symbol f}_c^*"}, {"gamma", "{/Symbol g}"},
      {"beta", "{/Symbol b}"},     {"width", "w"},                   {"porosity", "{/Symbol f}"},
      {"delta", "{/Symbol d}"},    {"C", "C"},                       {"A", "A"},
      {"e", "e"},                 {"particles", "N"},               {"scale", "s"}};
  const auto it = symbols.find(name);
  return it == symbols.end() ? enhanced_literal(name) : it->second;
}

std::string axis_label(const std::string& column) {
  static const std::map<std::string, std::string> labels{
      {"porosity", "porosity {/Symbol f}"},
      {"porosity_voxels", "porosity {/Symbol f} (voxels)"},
      {"delta", "voxel side {/Symbol d} / D_0"},
      {"scale", "radius scale s"},
      {"particles", "particles N"},
      {"percolates", "fraction percolating"},
      {"probability", "percolation probability P"},
      {"phi_c", "percolation threshold {/Symbol f}_c"},
      {"width", "transition width w"},
      {"permeability_delta2", "permeability {/Symbol k} / {/Symbol d}^2"},
      {"permeability_d02", "permeability {/Symbol k} / D_0^2"},
      {"permeability", "permeability {/Symbol k}"},
      {"rh_sites_d0", "hydraulic radius R_h / D_0"},
      {"rh_faces_d0", "hydraulic radius R_h / D_0 (faces)"},
      {"rh_sites_delta", "hydraulic radius R_h / {/Symbol d}"},
      {"rh_faces_delta", "hydraulic radius R_h / {/Symbol d} (faces)"},
      {"hydraulic_radius", "hydraulic radius R_h"},
      {"tortuosity", "hydraulic tortuosity {/Symbol t}_H"}};
  const auto it = labels.find(column);
  return it == labels.end() ? enhanced_literal(column) : it->second;
}

PlotPoints binned_outcomes(const std::vector<double>& x, const std::vector<double>& y, int bins) {
  PlotPoints p;
  if (x.empty() || bins < 1) return p;
  const double lo = *std::min_element(x.begin(), x.end()), hi = *std::max_element(x.begin(), x.end());
  const double width = hi > lo ? (hi - lo) / bins : 1.0;
  std::vector<double> sum_x(bins), ones(bins), count(bins);
  for (std::size_t i = 0; i < x.size(); ++i) {
    const int b = std::clamp(static_cast<int>((x[i] - lo) / width), 0, bins - 1);
    sum_x[b] += x[i], ones[b] += y[i], count[b] += 1;
  }
  for (int b = 0; b < bins; ++b) {
    if (count[b] == 0) continue;
    const double n = count[b], f = ones[b] / n, z2 = 1.0;  // z = 1: 68 %
    const double centre = (f + z2 / (2 * n)) / (1 + z2 / n);
    const double half = std::sqrt(f * (1 - f) / n + z2 / (4 * n * n)) / (1 + z2 / n);
    p.x.push_back(sum_x[b] / n);
    p.y.push_back(f);
    p.low.push_back(std::max(0.0, centre - half));
    p.high.push_back(std::min(1.0, centre + half));
  }
  return p;
}

std::string render_plot(PlotFormat format, const PlotSpec& spec) {
  std::string s;
  switch (format) {
    case PlotFormat::Png: {
      const std::string t = png_terminal();
      s += "set terminal " + t + " size 960,720" + (t == "pngcairo" ? " enhanced font 'Sans,13'" : " enhanced") + "\n";
      break;
    }
    case PlotFormat::Svg: s += "set terminal svg size 960,720 enhanced font 'Sans,13' background rgb 'white'\n"; break;
    case PlotFormat::Pdf: s += "set terminal pdfcairo size 6.4in,4.8in enhanced font 'Sans,11'\n"; break;
  }
  s += "set encoding utf8\nset xlabel " + quoted(spec.x_label) + "\nset ylabel " + quoted(spec.y_label) +
       "\nset title " + quoted(spec.title) + "\nset key below left Left reverse samplen 2\nset grid\n" +
       "set datafile missing 'NaN'\nset bars small\n";
  if (spec.log_y) s += "set logscale y\nset format y '10^{%L}'\n";
  if (spec.probability) s += "set yrange [-0.05:1.05]\n";
  else if (!spec.log_y) s += "set offsets 0, 0, graph 0.04, graph 0.04\n";
  for (std::size_t k = 0; k < spec.points.size(); ++k) {
    const auto& pts = spec.points[k];
    s += fmt::format("$points{} << EOD\n", k);
    for (std::size_t i = 0; i < pts.x.size(); ++i) {
      s += number(pts.x[i]) + ' ' + number(pts.y[i]);
      if (!pts.low.empty()) s += ' ' + number(pts.low[i]) + ' ' + number(pts.high[i]);
      s += '\n';
    }
    s += "EOD\n";
  }
  for (std::size_t c = 0; c < spec.curves.size(); ++c) {
    const auto& curve = spec.curves[c];
    s += fmt::format("$curve{} << EOD\n", c);
    const int samples = 400;
    for (int i = 0; i <= samples; ++i) {
      const double x = curve.from + (curve.to - curve.from) * i / samples;
      const double f = curve.model->value(x, curve.p.data());
      s += number(x) + ' ' + (std::isfinite(f) && (!spec.log_y || f > 0) ? number(f) : std::string("NaN")) + '\n';
    }
    s += "EOD\n";
  }
  std::vector<std::string> items;
  for (std::size_t k = 0; k < spec.points.size(); ++k) {
    const auto& pts = spec.points[k];
    const std::string colour = kPalette[k % kColours];
    const std::string title = pts.title.empty() ? "notitle" : "title " + quoted(pts.title);
    items.push_back(pts.low.empty()
                        ? fmt::format("$points{} using 1:2 with points pt 7 ps 0.6 lc rgb '{}' {}", k, colour, title)
                        : fmt::format("$points{} using 1:2:3:4 with yerrorbars pt 7 ps 0.8 lc rgb '{}' {}", k, colour, title));
  }
  for (std::size_t c = 0; c < spec.curves.size(); ++c) {
    const auto& curve = spec.curves[c];
    items.push_back(fmt::format("$curve{} using 1:2 with lines lw 2 dt {} lc rgb '{}' title {}", c, curve.dashed ? 2 : 1,
                                kPalette[curve.colour % kColours], quoted(curve.title)));
  }
  s += "plot ";
  for (std::size_t i = 0; i < items.size(); ++i) s += (i ? ", \\\n     " : "") + items[i];
  s += "\n";
  const Run r = run_gnuplot({}, s);
  if (WIFSIGNALED(r.status))
    throw ComputationError(fmt::format("gnuplot was killed by signal {} ({}) while drawing the plot",
                                       WTERMSIG(r.status), ::strsignal(WTERMSIG(r.status))));
  if (!succeeded(r) || r.out.empty())
    throw ComputationError(fmt::format("gnuplot failed{}: {}", WIFEXITED(r.status) ? fmt::format(" (exit status {})", WEXITSTATUS(r.status)) : "",
                                       r.err.empty() ? "no figure on its output" : messages(r.err)));
  return r.out;
}

}  // namespace cmp::fit
