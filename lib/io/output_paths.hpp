#pragma once
// The outputs of one run, checked before any work (docs/conventions.md, "Outputs"): each can be
// written (its folder exists and is writable, it is not a folder), no two of them are one file,
// and none of them is one of the run's inputs. Files are compared by what they are (device and
// inode of the file, or of its folder and its name when it does not exist yet), not by their
// spelling: `o.csv`, `./o.csv`, `dir/../o.csv`, a symbolic link to it and a hard link all count
// as one file. cli::Tool runs these checks on every output and input a program declares
// (Tool::add_output, Tool::declare_inputs) with the rest of its option checks.
#include <map>
#include <string>
#include <vector>

namespace cmp::io {

// Throws cmp::InputError(path, 0, "cannot write: <reason>") when path cannot be written as an
// AtomicOutput: an empty name, a name that is a folder, a folder that does not exist or is not
// writable. "-" (standard output) and an existing device or pipe that is writable pass.
void check_writable(const std::string& path);

// What a path names, the same string for two paths naming one regular file (existing or to
// be made by rename into its folder); empty for "-", for a device, pipe or socket (several
// outputs may share /dev/null), and when the folder does not exist.
std::string file_identity(const std::string& path);

// An output as the user gave it: the option and its value. A value holding a placeholder
// ('{seed}', '{name}', ...) is a pattern: its folder is checked with the placeholders filled
// in, and it is compared with the other outputs as written, in its resolved folder.
struct OutputPath {
  std::string flag;
  std::string path;
};
struct PathProblem {
  std::string flag;
  std::string message;
};
// Every problem of the outputs, in the order given: unwritable ("notadir/ck: cannot write: No
// such file or directory"), the same file as an earlier output ("same.csv is also the output
// of -o: two outputs of one run cannot share a file"), or an input ("j.xyz is also an input:
// the output would replace it"). "-" and empty values are skipped (the stdout rule is the
// program's).
// A pattern whose folder holds placeholders ('s{seed}/r.off') is checked in every folder its
// known values name (values: placeholder -> the values it takes, e.g. "seed" -> {"1", "2"}),
// "s3/r.off (from s{seed}/r.off): cannot write: No such file or directory"; a placeholder of
// the folder whose values are not known yet ({frame}) leaves that folder to the writer.
using PlaceholderValues = std::map<std::string, std::vector<std::string>>;
std::vector<PathProblem> output_path_problems(const std::vector<OutputPath>& outputs,
                                              const std::vector<std::string>& inputs,
                                              const PlaceholderValues& values = {});

}  // namespace cmp::io
