#include "milp/internal/mps_structure.h"

#include <algorithm>
#include <cctype>
#include <set>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "CoinMpsIO.hpp"  // COIN_MAX_FIELD_LENGTH, MAX_CARD_LENGTH: its fixed buffers

namespace thrustsched::milp::internal {
namespace {

// Section headers and their rank: a section may not follow one of a higher
// rank (0: anywhere before ROWS; the quadratic and SOS sections after COLUMNS).
struct Section {
  const char* name;
  int rank;
};
constexpr Section kSections[] = {{"NAME", 0},     {"OBJSENSE", 0}, {"OBJSENS", 0},  {"ROWS", 1},
                                 {"COLUMNS", 2},  {"RHS", 3},      {"RANGES", 4},   {"BOUNDS", 5},
                                 {"SOS", 6},      {"QUADOBJ", 6},  {"QSECTION", 6}, {"QMATRIX", 6},
                                 {"QCMATRIX", 6}, {"CSECTION", 6}, {"ENDATA", 7}};

const Section* FindSection(const std::string& word) {
  for (const Section& s : kSections) {
    if (word == s.name) return &s;
  }
  return nullptr;
}

[[noreturn]] void Fail(const std::string& path, int line, const std::string& what,
                       const std::string& why) {
  throw std::runtime_error("ReadMpsFile: '" + path + "' line " + std::to_string(line) + ": " +
                           what + ": " + why);
}

std::string Shown(const std::string& line) {
  std::string s;
  for (char c : line.substr(0, 40)) s += std::isprint(static_cast<unsigned char>(c)) ? c : '?';
  return "\"" + s + (line.size() > 40 ? "...\"" : "\"");
}

// CoinMpsIO's fixed-format reader takes the fields that start in columns 15
// and 40 as 8-character names; a longer one that is the last on its line
// (a line cut short: a value must follow it, or a long column name in a
// BOUNDS line without a value) makes it read through a null pointer
// (CoinMpsCardReader::nextField). Free-format files ("FREE" on the NAME
// line after the name) take another path.
void CheckFixedNameFields(const std::string& path, int number, const std::string& line) {
  // CoinMpsIO drops trailing blanks before it looks.
  const std::string card = line.substr(0, line.find_last_not_of(" \t") + 1);
  auto blank = [](char c) { return c == ' ' || c == '\t'; };
  for (const size_t column : {size_t{14}, size_t{39}}) {
    const bool starts_here =
        card.size() > column && !blank(card[column]) && blank(card[column - 1]);
    if (starts_here && card.size() > column + 8 &&
        card.find_first_of(" \t", column) == std::string::npos) {
      Fail(path, number, Shown(card.substr(column)),
           "a name of more than 8 characters in column " + std::to_string(column + 1) +
               " ends the line (fixed-format MPS; a value must follow, or mark the file FREE)");
    }
  }
}

// CoinMpsIO expands the tabs of a fixed-format BOUNDS line to its columns
// and asserts (aborts) that the line is under 81 characters.
void CheckFixedBoundsTabs(const std::string& path, int number, const std::string& line) {
  const size_t end = line.find_last_not_of(" \t");
  if (line.find('\t') == std::string::npos || end == std::string::npos || end + 1 <= 80) return;
  Fail(path, number, Shown(line),
       "a BOUNDS line with tabs longer than 80 characters (fixed-format MPS; mark the file FREE)");
}

bool NameLineSaysFree(const std::string& line) {
  std::istringstream words(line);
  std::string word;
  words >> word >> word;  // "NAME", then the problem's name
  while (words >> word) {
    if (word.find("FREE") != std::string::npos) return true;
  }
  return false;
}

}  // namespace

void CheckMpsStructure(const std::string& path, std::istream& in) {
  std::set<std::string> seen;
  int rank = 0;
  bool ended = false;
  bool free_format = false;
  std::string section;
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    // CoinMpsIO strcpy()s lines and fields into fixed buffers (a 170-character
    // problem name overflowed one).
    if (line.size() >= static_cast<size_t>(MAX_CARD_LENGTH)) {
      Fail(path, number, Shown(line),
           "line longer than " + std::to_string(MAX_CARD_LENGTH - 1) + " characters");
    }
    for (size_t a = line.find_first_not_of(" \t"); a != std::string::npos;) {
      const size_t b = std::min(line.find_first_of(" \t", a), line.size());
      if (b - a >= static_cast<size_t>(COIN_MAX_FIELD_LENGTH)) {
        Fail(path, number, Shown(line.substr(a)),
             "field longer than " + std::to_string(COIN_MAX_FIELD_LENGTH - 1) + " characters");
      }
      a = line.find_first_not_of(" \t", b);
    }
    for (char c : line) {
      const auto u = static_cast<unsigned char>(c);
      if (u != '\t' && (u < 32 || u > 126)) {
        Fail(path, number, Shown(line), "byte " + std::to_string(u) + " is not printable ASCII");
      }
    }
    if (line.find_first_not_of(" \t") == std::string::npos || line[0] == '*') continue;
    if (ended) Fail(path, number, Shown(line), "text after ENDATA");
    if (line[0] == ' ' || line[0] == '\t') {
      if (seen.empty()) {
        Fail(path, number, Shown(line), "data line before any section");
      }
      if (!free_format) CheckFixedNameFields(path, number, line);
      if (!free_format && section == "BOUNDS") CheckFixedBoundsTabs(path, number, line);
      continue;
    }
    const std::string word = line.substr(0, line.find_first_of(" \t"));
    const Section* s = FindSection(word);
    if (s == nullptr) {
      Fail(path, number, word, "not a section header (data lines start with a blank)");
    }
    if (seen.empty() && word != "NAME") {
      Fail(path, number, word, "the first section must be NAME");
    }
    if (!seen.insert(word).second) Fail(path, number, word, "section appears a second time");
    if (s->rank < rank) Fail(path, number, word, "section out of order");
    if (s->rank >= 3 && seen.count("COLUMNS") == 0) {
      Fail(path, number, word, "section before ROWS and COLUMNS");
    }
    if (s->rank == 2 && seen.count("ROWS") == 0) Fail(path, number, word, "COLUMNS before ROWS");
    if (word == "NAME") free_format = NameLineSaysFree(line);
    section = word;
    rank = s->rank;
    ended = s->rank == 7;
  }
  if (!ended) Fail(path, number, "ENDATA", "missing (the file ends without it)");
}

}  // namespace thrustsched::milp::internal
