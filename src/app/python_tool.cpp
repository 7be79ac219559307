#include "app/python_tool.hpp"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>

extern char** environ;

namespace crumple::app {
namespace {

std::string envOr(const char* name, const std::string& fallback) {
  const char* value = std::getenv(name);
  return value && *value ? std::string(value) : fallback;
}

// The environment of the child: ours, with the package folder first on PYTHONPATH and no
// bytecode written into the source tree.
std::vector<std::string> childEnvironment(const std::string& package_dir) {
  std::vector<std::string> env;
  std::string path = package_dir;
  for (char** e = environ; *e; ++e) {
    const std::string entry(*e);
    if (entry.rfind("PYTHONPATH=", 0) == 0)
      path += ":" + entry.substr(11);
    else if (entry.rfind("PYTHONDONTWRITEBYTECODE=", 0) != 0)
      env.push_back(entry);
  }
  env.push_back("PYTHONPATH=" + path);
  env.push_back("PYTHONDONTWRITEBYTECODE=1");
  return env;
}

std::vector<char*> pointers(std::vector<std::string>& strings) {
  std::vector<char*> out;
  for (auto& s : strings) out.push_back(s.data());
  out.push_back(nullptr);
  return out;
}

// posix_spawn, not exec: MPI was initialised in main() and is finalised after we return.
int spawnAndWait(const std::string& tool, std::vector<std::string> argv,
                 std::vector<std::string> env) {
  auto args = pointers(argv);
  auto envp = pointers(env);
  pid_t pid = 0;
  if (posix_spawn(&pid, args[0], nullptr, nullptr, args.data(), envp.data()) != 0) {
    std::fprintf(stderr, "crumple %s: error: cannot start %s\n", tool.c_str(), args[0]);
    return 1;
  }
  int status = 0;
  if (waitpid(pid, &status, 0) < 0) return 1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : 1;
}

}  // namespace

int pythonToolCommand(const std::string& tool, const std::string& module,
                      const std::vector<std::string>& args) {
  const std::string python = envOr("CRUMPLE_PYTHON", "/usr/bin/python3");
  const std::string package_dir = envOr("CRUMPLE_COMPARE_DIR", CRUMPLE_PYTHON_DIR);
  if (access(python.c_str(), X_OK) != 0) {
    std::fprintf(stderr,
                 "crumple %s: error: no Python interpreter at %s (install python3, "
                 "python3-numpy and python3-matplotlib, or set CRUMPLE_PYTHON)\n",
                 tool.c_str(), python.c_str());
    return 1;
  }
  if (!std::filesystem::is_regular_file(std::filesystem::path(package_dir) / "crumple_compare" /
                                        "__main__.py")) {
    std::fprintf(stderr,
                 "crumple %s: error: the crumple_compare package is not in %s (set "
                 "CRUMPLE_COMPARE_DIR to the folder that holds it)\n",
                 tool.c_str(), package_dir.c_str());
    return 1;
  }
  std::vector<std::string> argv = {python, "-m", module};
  argv.insert(argv.end(), args.begin(), args.end());
  return spawnAndWait(tool, std::move(argv), childEnvironment(package_dir));
}

}  // namespace crumple::app
