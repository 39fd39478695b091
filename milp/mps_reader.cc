#include "milp/mps_reader.h"

#include <cmath>
#include <fstream>
#include <stdexcept>
#include <string>

#include "milp/internal/mps_structure.h"

#include "CoinMessageHandler.hpp"
#include "CoinMpsIO.hpp"
#include "CoinPackedMatrix.hpp"

namespace thrustsched::milp {
namespace {

// Drops every message: reading prints nothing.
class SilentHandler : public CoinMessageHandler {
 public:
  SilentHandler() { setLogLevel(0); }
  int print() override { return 0; }
  CoinMessageHandler* clone() const override { return new SilentHandler(*this); }
};

}  // namespace

LpData ReadMpsFile(const std::string& path) {
  {
    std::ifstream probe(path);
    if (!probe) throw std::runtime_error("ReadMpsFile: cannot open '" + path + "'");
    internal::CheckMpsStructure(path, probe);
  }
  SilentHandler silent;
  CoinMpsIO mps;
  mps.passInMessageHandler(&silent);
  mps.messageHandler()->setLogLevel(0);
  // Keep every value exactly: CoinMpsIO drops |v| < 1e-14 by default.
  mps.setSmallElementValue(0.0);
  const int errors = mps.readMps(path.c_str(), "");
  if (errors != 0) {
    throw std::runtime_error("ReadMpsFile: '" + path + "' has " + std::to_string(errors) +
                             " read error(s)");
  }
  const int n = mps.getNumCols();
  const int m = mps.getNumRows();
  const double infinity = mps.getInfinity();
  auto value = [infinity](double v) {
    if (v >= infinity) return kInfinity;
    if (v <= -infinity) return -kInfinity;
    return v;
  };
  LpData lp;
  lp.name = mps.getProblemName();
  lp.sense = ObjectiveSense::kMinimize;
  // CoinMpsIO stores the objective constant with the sign of an RHS entry.
  lp.objective_offset = -mps.objectiveOffset();
  lp.col_cost.resize(n);
  lp.col_lower.resize(n);
  lp.col_upper.resize(n);
  lp.col_type.resize(static_cast<size_t>(n));
  const double* cost = mps.getObjCoefficients();
  const double* cl = mps.getColLower();
  const double* cu = mps.getColUpper();
  for (int j = 0; j < n; ++j) {
    lp.col_cost[j] = cost[j];
    lp.col_lower[j] = value(cl[j]);
    lp.col_upper[j] = value(cu[j]);
    VarType t = VarType::kContinuous;
    if (mps.isInteger(j)) {
      t = (lp.col_lower[j] == 0.0 && lp.col_upper[j] == 1.0) ? VarType::kBinary : VarType::kInteger;
    }
    lp.col_type[static_cast<size_t>(j)] = t;
    lp.col_names.push_back(mps.columnName(j));
  }
  lp.row_lower.resize(m);
  lp.row_upper.resize(m);
  const double* rl = mps.getRowLower();
  const double* ru = mps.getRowUpper();
  for (int i = 0; i < m; ++i) {
    lp.row_lower[i] = value(rl[i]);
    lp.row_upper[i] = value(ru[i]);
    lp.row_names.push_back(mps.rowName(i));
  }
  CoinPackedMatrix by_col(*mps.getMatrixByCol());
  by_col.removeGaps();
  if (!by_col.isColOrdered()) by_col.reverseOrdering();
  std::vector<Eigen::Triplet<double, int>> triplets;
  triplets.reserve(static_cast<size_t>(by_col.getNumElements()));
  const CoinBigIndex* start = by_col.getVectorStarts();
  const int* length = by_col.getVectorLengths();
  const int* index = by_col.getIndices();
  const double* element = by_col.getElements();
  for (int j = 0; j < by_col.getMajorDim(); ++j) {
    for (CoinBigIndex k = start[j]; k < start[j] + length[j]; ++k) {
      if (element[k] != 0.0) triplets.emplace_back(index[k], j, element[k]);
    }
  }
  lp.a_matrix.resize(m, n);
  lp.a_matrix.setFromTriplets(triplets.begin(), triplets.end());
  lp.a_matrix.makeCompressed();
  std::string error;
  if (!lp.IsValid(&error)) {
    throw std::runtime_error("ReadMpsFile: '" + path + "' gives an invalid model: " + error);
  }
  return lp;
}

}  // namespace thrustsched::milp
