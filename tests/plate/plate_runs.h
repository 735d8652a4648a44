#pragma once

// Run the plate scene from a test: parameters from text, solver by name,
// results kept in memory (summary.json goes to results/<name>/, never to a
// directory named "output", which deal.II's test driver reserves).

#include <unilateral/lcp/solver.h>
#include <unilateral/scenes/plate/plate_scene.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace plate_runs
{
  struct Run
  {
    /// The scene after its run: results(), nodal_values(), the mesh.
    std::unique_ptr<unilateral::plate::PlateScene> scene;
    unilateral::lcp::Report                        report;
    /// What the run printed (its summary).
    std::string printed;

    const unilateral::plate::PlateScene::Results &
    results() const
    {
      return scene->results();
    }
  };

  /// The "subsection Plate" body of a paper configuration.
  inline std::string
  paper_configuration(const std::string &material,
                      const std::string &obstacle,
                      const std::string &force,
                      const unsigned int n,
                      const std::string &boundary = "clamped")
  {
    std::ostringstream text;
    text << "subsection Geometry\n  set Elements x = " << n
         << "\n  set Elements y = " << n
         << "\n  set Boundary condition = " << boundary << "\nend\n"
         << "subsection Material\n  set Name = " << material << "\nend\n"
         << "subsection Obstacle\n  set Function = " << obstacle << "\nend\n"
         << "subsection Load\n  set Force = " << force << "\nend\n";
    return text.str();
  }

  /// Run the scene with @p plate_parameters and solver @p method (its
  /// registered name; an unknown name fails the test loudly), with more
  /// "set ..." lines for subsection Solver in @p solver_settings.
  inline Run
  run_plate(const std::string &name,
            const std::string &plate_parameters,
            const std::string &method,
            const bool         write_vtu       = false,
            const std::string &solver_settings = "")
  {
    unilateral::RunContext   context;
    dealii::ParameterHandler prm;
    context.solver.declare_parameters(prm);
    unilateral::plate::PlateScene::declare_parameters(prm);
    prm.parse_input_from_string(
      "subsection Solver\n  set Method = " + method + "\n" + solver_settings +
      "end\nsubsection Plate\n" + plate_parameters + "end\n");

    context.run_name = name;
    context.solver.parse_parameters(prm);
    auto scene = std::make_unique<unilateral::plate::PlateScene>(prm);
    context.output_directory = std::filesystem::path("results") / name;
    std::filesystem::create_directories(context.output_directory);
    context.write_vtu = write_vtu;

    std::ostringstream  screen;
    dealii::TimerOutput timer(screen,
                              dealii::TimerOutput::never,
                              dealii::TimerOutput::wall_times);
    context.out   = &screen;
    context.timer = &timer;

    Run run;
    run.report  = scene->run(context);
    run.scene   = std::move(scene);
    run.printed = screen.str();
    return run;
  }

  /// One row of the paper's Tables 1-6 (benchmarks/plate_tables).
  struct PaperRow
  {
    unsigned int table;
    std::string  material, obstacle, force; ///< force as f1, f2, f3
    unsigned int n;                         ///< n1 = n2
    unsigned int n_free, n_bounds, n_contact;
  };

  inline std::vector<PaperRow>
  read_paper_tables(const std::string &file_name)
  {
    std::ifstream                            file(file_name);
    std::vector<PaperRow>                    rows;
    std::string                              line;
    const std::map<std::string, std::string> force_name = {{"-1", "f1"},
                                                           {"-5", "f2"},
                                                           {"-10", "f3"}};
    while (std::getline(file, line))
      {
        if (line.empty() || line[0] == '#' || line.rfind("table", 0) == 0)
          continue;
        std::vector<std::string> field;
        std::stringstream        fields(line);
        std::string              item;
        while (std::getline(fields, item, ','))
          field.push_back(item);
        PaperRow row;
        row.table              = std::stoi(field[0]);
        row.material           = field[1];
        row.obstacle           = field[2];
        row.force              = force_name.at(field[3]);
        const unsigned int ele = std::stoi(field[4]);
        row.n                  = 0;
        while (row.n * row.n < ele)
          ++row.n;
        row.n_free    = std::stoi(field[5]);
        row.n_bounds  = std::stoi(field[6]);
        row.n_contact = std::stoi(field[7]);
        rows.push_back(row);
      }
    return rows;
  }
} // namespace plate_runs
