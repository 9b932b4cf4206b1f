// lib/io/atomic_output.hpp: a file appears under its final name only when complete.
#include "io/atomic_output.hpp"

#include "io_test_support.hpp"

#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <fcntl.h>
#include <unistd.h>

using namespace cmp;
using namespace cmp::io;
using namespace cmp::io::test;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

TEST_CASE("AtomicOutput shows the file only after commit", "[atomic_output]") {
  TempDir dir;
  const auto path = dir.file("out.txt");
  AtomicOutput out(path);
  out.stream() << "hello\n";
  // Before commit: only the hidden temporary file, in the same folder.
  auto names = dir.entries();
  REQUIRE(names.size() == 1);
  CHECK_THAT(names[0], StartsWith(".out.txt.tmp."));
  out.commit();
  CHECK(dir.entries() == std::vector<std::string>{"out.txt"});
  CHECK(read_text(path) == "hello\n");
  CHECK(out.path() == path);
}

TEST_CASE("AtomicOutput gives the file mode 0644 minus the umask", "[atomic_output]") {
  TempDir dir;
  const mode_t old = ::umask(027);
  {
    AtomicOutput out(dir.file("a"));
    out.stream() << "x";
    out.commit();
  }
  ::umask(old);
  struct stat st {};
  REQUIRE(::stat(dir.file("a").c_str(), &st) == 0);
  CHECK((st.st_mode & 0777) == 0640);
}

TEST_CASE("AtomicOutput without commit leaves nothing, and keeps an older file",
          "[atomic_output]") {
  TempDir dir;
  const auto path = dir.file("result.csv");
  SECTION("abandoned") {
    {
      AtomicOutput out(path);
      out.stream() << "partial";
    }
    CHECK(dir.entries().empty());
  }
  SECTION("an exception before commit") {
    write_text(path, "old contents\n");
    try {
      AtomicOutput out(path);
      out.stream() << "half a fi";
      throw std::runtime_error("interrupted");
    } catch (const std::runtime_error&) {
    }
    CHECK(dir.entries() == std::vector<std::string>{"result.csv"});
    CHECK(read_text(path) == "old contents\n");
  }
}

TEST_CASE("AtomicOutput replaces an existing file on commit", "[atomic_output]") {
  TempDir dir;
  const auto path = dir.file("f");
  write_text(path, "old");
  AtomicOutput out(path);
  out.stream() << "new";
  out.commit();
  out.commit();  // a second commit does nothing
  CHECK(read_text(path) == "new");
  CHECK(dir.entries() == std::vector<std::string>{"f"});
}

TEST_CASE("AtomicOutput reports folders it cannot write", "[atomic_output]") {
  TempDir dir;
  SECTION("missing folder") {
    const auto path = dir.file("missing/out.txt");
    CHECK(input_error([&] { AtomicOutput out(path); }) ==
          path + ": cannot write: No such file or directory");
  }
  SECTION("the target is a folder: the rename fails and the temporary file goes") {
    std::filesystem::create_directory(dir.file("sub"));
    const auto msg = input_error([&] {
      AtomicOutput out(dir.file("sub"));
      out.stream() << "x";
      out.commit();
    });
    CHECK_THAT(msg, StartsWith(dir.file("sub") + ": cannot write: "));
    CHECK(dir.entries() == std::vector<std::string>{"sub"});
  }
  SECTION("a parent that is a regular file (a failure no permission bypasses, so it holds as root too)") {
    std::ofstream(dir.file("plain")) << "x";
    const std::string path = dir.file("plain/out.txt");
    CHECK(input_error([&] { AtomicOutput out(path); }) == path + ": cannot write: Not a directory");
    CHECK(dir.entries() == std::vector<std::string>{"plain"});
  }
  SECTION("an empty name") {
    CHECK_THAT(input_error([&] { AtomicOutput out(""); }), Contains("cannot write"));
  }
}

TEST_CASE("AtomicOutput writes standard output for '-'", "[atomic_output]") {
  StdoutTo capture;
  AtomicOutput out("-");
  out.stream() << "to stdout\n";
  out.commit();
  CHECK(capture.text() == "to stdout\n");
}

TEST_CASE("AtomicOutput reports a full disk at commit", "[atomic_output]") {
  // /dev/full accepts the open and fails every write; its folder is not writable for a
  // temporary file, so simulate by writing more than the buffer to a stream in a failed state.
  TempDir dir;
  const auto path = dir.file("x");
  AtomicOutput out(path);
  out.stream().setstate(std::ios::badbit);  // what a failed write leaves behind
  CHECK_THAT(input_error([&] { out.commit(); }), StartsWith(path + ": write error"));
  CHECK(dir.entries().empty());
}

TEST_CASE("AtomicOutput reports a write the file size limit stops, as root too", "[atomic_output]") {
  // RLIMIT_FSIZE binds root as well: in a child limited to 4 KiB, writing 64 KiB fails with
  // EFBIG; commit must say "write error" and leave no file.
  TempDir dir;
  const auto path = dir.file("big.txt");
  const pid_t child = ::fork();
  REQUIRE(child >= 0);
  if (child == 0) {
    ::signal(SIGXFSZ, SIG_IGN);
    rlimit limit{4096, 4096};
    ::setrlimit(RLIMIT_FSIZE, &limit);
    int status = 3;
    try {
      AtomicOutput out(path);
      out.stream() << std::string(65536, 'x');
      out.commit();
      status = 4;  // the limit was not noticed
    } catch (const cmp::InputError& e) {
      status = std::string(e.what()).rfind(path + ": write error", 0) == 0 ? 0 : 5;
    }
    ::_exit(status);
  }
  int status = 0;
  REQUIRE(::waitpid(child, &status, 0) == child);
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 0);
  CHECK(dir.entries().empty());
}

TEST_CASE("AtomicOutput creates its temporary at the first write, not before", "[atomic_output]") {
  TempDir dir;
  AtomicOutput out(dir.file("late.csv"));
  CHECK(dir.entries().empty());  // a long computation leaves nothing while it runs
  out.stream() << "a\n";
  CHECK(dir.entries().size() == 1);
  out.commit();
  CHECK(dir.entries() == std::vector<std::string>{"late.csv"});
}

TEST_CASE("The temporary registry removes what an interrupted run would leave", "[atomic_output]") {
  TempDir dir;
  AtomicOutput out(dir.file("partial.csv"));
  out.stream() << "half a table\n";
  std::filesystem::create_directory(dir.file("plot.tmp"));
  cmp::io::TemporaryPath folder(dir.file("plot.tmp"), cmp::io::TemporaryPath::Kind::Directory);
  std::ofstream(dir.file("plot.tmp/fit.png")) << "png";
  cmp::io::TemporaryPath png(dir.file("plot.tmp/fit.png"));
  CHECK(folder.registered());
  CHECK(png.registered());
  std::ofstream(dir.file("keep.txt")) << "not registered";
  REQUIRE(dir.entries().size() == 3);
  cmp::io::remove_registered_temporaries();  // what the SIGINT handler calls
  CHECK(dir.entries() == std::vector<std::string>{"keep.txt"});
  // A committed output is no longer registered.
  AtomicOutput done(dir.file("done.csv"));
  done.stream() << "x\n";
  done.commit();
  cmp::io::remove_registered_temporaries();
  CHECK(std::filesystem::exists(dir.file("done.csv")));
}

TEST_CASE("AtomicOutput writes a FIFO (or a device such as /dev/null) in place, never replacing it", "[atomic_output]") {
  TempDir dir;
  const auto fifo = dir.file("pipe");
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  // Held open for reading and writing (Linux), so the writer's open does not block and the
  // test cannot hang when the output goes elsewhere.
  const int fd = ::open(fifo.c_str(), O_RDWR | O_NONBLOCK);
  REQUIRE(fd >= 0);
  {
    AtomicOutput out(fifo);
    out.stream() << "through the pipe\n";
    out.commit();
  }
  char buffer[64] = {};
  const auto n = ::read(fd, buffer, sizeof buffer);
  ::close(fd);
  const std::string received(buffer, n > 0 ? static_cast<std::size_t>(n) : 0);
  CHECK(received == "through the pipe\n");
  struct stat st {};
  REQUIRE(::stat(fifo.c_str(), &st) == 0);
  CHECK(S_ISFIFO(st.st_mode));  // a rename would have put a regular file here
  CHECK(dir.entries() == std::vector<std::string>{"pipe"});  // no temporary left beside it
  // A folder is still refused.
  CHECK_THROWS_AS(AtomicOutput(dir.path().string()), InputError);
}
