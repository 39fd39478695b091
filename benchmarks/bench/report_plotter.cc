#include "benchmarks/bench/report_plotter.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace thrustsched::bench::report_internal {

void Plotter::Run(const std::string& name, const std::string& script) {
  const std::string pdir = dir + "/plots";
  std::filesystem::create_directories(pdir);
  {
    std::ofstream gp(pdir + "/" + name + ".gp");
    gp << "set terminal svg size 900,540 dynamic noenhanced font 'sans,12'\n"
       << "set output '../" << name << ".svg'\n"
       << script;
  }
  if (!gnuplot) return;
  const std::string cmd =
      "cd '" + pdir + "' && gnuplot '" + name + ".gp' > '" + name + ".log' 2>&1";
  if (std::system(cmd.c_str()) == 0 && std::filesystem::exists(dir + "/" + name + ".svg")) {
    made.push_back(name + ".svg");
  } else {
    failed.push_back(name + ".svg");
  }
}

std::string Plotter::Data(const std::string& name, const std::string& text) {
  std::filesystem::create_directories(dir + "/plots");
  std::ofstream out(dir + "/plots/" + name);
  out << text;
  return name;
}

std::string Plotter::Link(const std::string& name, const std::string& alt) const {
  return "![" + alt + "](" + name + ".svg)\n\n";
}

}  // namespace thrustsched::bench::report_internal
