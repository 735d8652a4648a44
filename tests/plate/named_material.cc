// A named material (steel, bronze, lead) brings its own E and nu; a
// 'Young's modulus' or 'Poisson's ratio' set beside it with another value
// would be ignored, so it is refused with one line naming both parameters
// (issue 21: it was ignored without a word). The same value as the named
// material's, or no value, is fine, and so is Name = custom; in other
// Plate/Units the material's own is its value converted, to rounding.
#include "../application_test_tools.h"

using namespace application_test;

namespace
{
  Result
  run_material(const std::string &name,
               const std::string &material_lines,
               const std::string &units = "mm and kg")
  {
    write(name + ".prm",
          "set Scene = plate\n"
          "subsection Output\n  set Directory = results\n"
          "  set Write VTU = false\n  set Print timings = false\n"
          "  set Progress = false\nend\n"
          "subsection Plate\n  set Units = " +
            units +
            "\n  subsection Geometry\n"
            "    set Elements x = 8\n    set Elements y = 8\n  end\n"
            "  subsection Material\n" +
            material_lines + "  end\nend\n");
    return run({name + ".prm"});
  }

  void
  expect_run(const std::string &what, const Result &result)
  {
    std::cout << what << ": exit code 0: " << yes_no(result.code == 0)
              << ", error output empty: " << yes_no(result.err.empty()) << "\n";
  }
} // namespace

int
main()
{
  expect_error("steel with Poisson's ratio = 0.3",
               run_material("steel_nu",
                            "    set Name = steel\n"
                            "    set Poisson's ratio = 0.3\n"),
               {"'Plate/Material/Poisson's ratio' = 0.3",
                "'Plate/Material/Name' = steel",
                "custom"});
  expect_error("lead with Young's modulus = 5000",
               run_material("lead_E",
                            "    set Name = lead\n"
                            "    set Young's modulus = 5000\n"),
               {"'Plate/Material/Young's modulus' = 5000",
                "'Plate/Material/Name' = lead",
                "custom"});
  expect_error("bronze with the default's values set explicitly",
               run_material("bronze_defaults",
                            "    set Name = bronze\n"
                            "    set Poisson's ratio = 0.28\n"),
               {"'Plate/Material/Poisson's ratio' = 0.28",
                "'Plate/Material/Name' = bronze"});

  expect_run("steel alone", run_material("steel", "    set Name = steel\n"));
  expect_run("bronze alone (its nu differs from the default 0.28)",
             run_material("bronze", "    set Name = bronze\n"));
  expect_run("steel with its own E and nu set",
             run_material("steel_same",
                          "    set Name = steel\n"
                          "    set Young's modulus = 21e3\n"
                          "    set Poisson's ratio = 0.28\n"));
  // 1800 kg/mm^2 in N/mm^2 is 17651.969999999998 (a review: refused).
  expect_run("lead in mm and N with its own E converted",
             run_material("lead_newton",
                          "    set Name = lead\n"
                          "    set Young's modulus = 17651.97\n",
                          "mm and N"));
  expect_error("lead in mm and N with E in kg/mm^2",
               run_material("lead_newton_kg",
                            "    set Name = lead\n"
                            "    set Young's modulus = 1800\n",
                            "mm and N"),
               {"'Plate/Material/Young's modulus' = 1800",
                "has its own (17651.97)"});
  expect_run("custom with E and nu",
             run_material("custom",
                          "    set Name = custom\n"
                          "    set Young's modulus = 7000\n"
                          "    set Poisson's ratio = 0.33\n"));
}
