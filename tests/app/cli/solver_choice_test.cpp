// The solvers as the command line, the panel and the plots name them.
#include "app/cli/solver_choice.h"

#include <gtest/gtest.h>

#include "sim/input_error.h"

namespace {

TEST(SolverChoice, ListsTheRegisteredSolversDefaultFirst) {
  EXPECT_EQ(wobble::solver_names(), (std::vector<std::string>{"local-global", "lbfgs"}));
  EXPECT_EQ(wobble::solver_index("local-global"), 0);
  EXPECT_EQ(wobble::solver_index("lbfgs"), 1);
  EXPECT_EQ(wobble::solver_index("newton"), 0) << "an unknown name shows as the default";
}

TEST(SolverChoice, LabelsNameTheMethodAndChebyshevWhereItApplies) {
  EXPECT_EQ(wobble::solver_label("local-global"), "local-global");
  EXPECT_EQ(wobble::solver_label("local-global", true), "local-global (Chebyshev)");
  EXPECT_EQ(wobble::solver_label("lbfgs"), "L-BFGS");
  EXPECT_EQ(wobble::solver_label("lbfgs", true), "L-BFGS") << "Chebyshev does not apply";
  EXPECT_TRUE(wobble::solver_takes_chebyshev("local-global"));
  EXPECT_FALSE(wobble::solver_takes_chebyshev("lbfgs"));
}

TEST(SolverChoice, ParsingRefusesAnUnknownNameListingTheChoices) {
  EXPECT_EQ(wobble::parse_solver("--solver", "lbfgs"), "lbfgs");
  EXPECT_EQ(wobble::parse_solver("--solver", "local-global"), "local-global");
  for (const char* wrong : {"L-BFGS", "", "lbfgs ", "newton"}) {
    try {
      wobble::parse_solver("--solver", wrong);
      ADD_FAILURE() << "accepted '" << wrong << "'";
    } catch (const wobble::InputError& error) {
      EXPECT_EQ(std::string(error.what()),
                std::string("--solver: expected local-global or lbfgs, got '") + wrong + "'");
    }
  }
}

}  // namespace
