#include <unilateral/application.h>
#include <unilateral/base/blas_threads.h>
#include <unilateral/base/input_error.h>
#include <unilateral/base/memory.h>
#include <unilateral/base/output_file.h>
#include <unilateral/base/parameter_file_errors.h>
#include <unilateral/base/prefixed_lines.h>
#include <unilateral/base/ranks.h>
#include <unilateral/base/version.h>
#include <unilateral/scenes/lcp_scene.h>
#include <unilateral/scenes/scene.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

namespace unilateral
{
  namespace
  {
    const char *usage_text =
      "unilateral: frictionless contact problems as linear complementarity "
      "problems.\n"
      "\n"
      "Usage:\n"
      "  unilateral FILE.prm                run the scene FILE.prm describes\n"
      "  unilateral --print-parameters [prm|json]\n"
      "                                     print every parameter with its\n"
      "                                     documentation and default\n"
      "  unilateral --version               the git commit built and the\n"
      "                                     deal.II it runs on\n"
      "  unilateral --help (or -h)          this text\n"
      "\n"
      "A run writes into <Output/Directory>/<Output/Run name>/ (by default\n"
      "output/<name of FILE>/ in the working directory; relative paths in\n"
      "FILE are taken from FILE's folder): summary.json, a copy of FILE.prm,\n"
      "and VTU/PVD files for ParaView. Exit code: 0 converged, 1 bad input\n"
      "(or a problem too large for the memory), 2 the solver did not\n"
      "converge (its status is in summary.json), 3 an internal error (a\n"
      "defect of the program or a failure of a library it calls, not of\n"
      "the input: please report it with the parameter file).\n";

    /// A run that failed for a reason not in its input: a consistency check
    /// of the program (std::logic_error) or a failure a library reported
    /// (CHOLMOD, MUMPS, PETSc, MPI). Exit code 3.
    class InternalError : public std::runtime_error
    {
    public:
      using std::runtime_error::runtime_error;
    };

    /// A thread the system would not start (TBB reports pthread_create's
    /// EAGAIN as a runtime error): a limit of the system on threads
    /// ('ulimit -u') or on the address space their stacks take ('ulimit
    /// -v'), not a defect of the program.
    bool
    thread_refused(const std::exception &error)
    {
      return std::string(error.what()).find("pthread_create") !=
             std::string::npos;
    }

    /// Whether @p error is not the input's fault: a check of the program's
    /// own consistency (std::logic_error), or a library's failure (CHOLMOD,
    /// MUMPS, PETSc and MPI report theirs as runtime errors). Not an
    /// InputError, nor what the system refused (files and folders:
    /// std::system_error, the user's to fix; threads), nor input a library
    /// refuses (deal.II's mesh readers throw neither kind).
    bool
    is_internal(const std::exception &error)
    {
      if (dynamic_cast<const InputError *>(&error) != nullptr ||
          dynamic_cast<const std::system_error *>(&error) != nullptr ||
          thread_refused(error))
        return false;
      return dynamic_cast<const std::logic_error *>(&error) != nullptr ||
             dynamic_cast<const std::runtime_error *>(&error) != nullptr;
    }

    // The default scene: the masonry wall, the program's first use.
    std::string
    default_scene()
    {
      for (const auto &scene : SceneRegistry::all())
        if (scene.name == "masonry")
          return scene.name;
      return SceneRegistry::all().front().name;
    }

    // Every parameter; the solver methods' own are bound to @p solver.
    void
    declare_parameters(dealii::ParameterHandler &prm,
                       lcp::SolverParameters    &solver)
    {
      prm.declare_entry("Scene",
                        default_scene(),
                        dealii::Patterns::Selection(SceneRegistry::selection()),
                        "Which problem to build and solve:\n" +
                          SceneRegistry::documentation());
      prm.declare_entry(
        "Memory limit",
        "0",
        dealii::Patterns::Double(0),
        "Most memory the run may use, in GB; 0: the machine's available "
        "memory. Under MPI it bounds each rank, against the memory its "
        "machine has left (ranks on one machine share it). Before building "
        "the matrix, ordering it and allocating a Cholesky factor, the run "
        "checks that these fit, and stops with a "
        "message naming the parameters that make the problem smaller (and "
        "this one first where it, not the machine, is the bound) instead of "
        "being killed by the kernel half-way (exit code 1).");
      prm.enter_subsection("Output");
      {
        prm.declare_entry("Directory",
                          "",
                          dealii::Patterns::FileName(
                            dealii::Patterns::FileName::output),
                          "Where runs write; each run in its own "
                          "subdirectory named by 'Run name'. Empty: output/ "
                          "in the working directory. A relative path is "
                          "taken from the folder of the parameter file, like "
                          "every path in it.");
        prm.declare_entry("Run name",
                          "",
                          dealii::Patterns::Anything(),
                          "Name of this run's subdirectory of 'Directory' "
                          "(a plain name: no '/' or '\\', not '.' or "
                          "'..'); empty takes the parameter file's name "
                          "without extension. A run first removes from it "
                          "the files an earlier run wrote there "
                          "(summary.json, parameters.prm (.json, .xml), "
                          "the scenes' "
                          "solution.pvd, solution_NNN.vtu and .pvtu with "
                          "their pieces, plate.* and nodes.* VTU and PVD "
                          "files, u.txt, lambda.txt, active_set.txt, "
                          "lcp_A.mtx, lcp_b.txt, lcp_constraints.txt) and "
                          "nothing else: other VTU files there stay.");
        prm.declare_entry("Write VTU",
                          "true",
                          dealii::Patterns::Bool(),
                          "Write VTU/PVD files for ParaView (false skips all "
                          "field output and the work it needs).");
        prm.declare_entry("Export LCP",
                          "false",
                          dealii::Patterns::Bool(),
                          "Write the LCP (lcp_A.mtx, lcp_b.txt, "
                          "lcp_constraints.txt) in the format the lcp scene "
                          "reads, so other tools can solve exactly our "
                          "problem. The masonry scene's LCP is in the "
                          "solvers' force unit k (the largest Young's "
                          "modulus / 4e3) and leaves out the energy e of "
                          "prescribed displacements: its energy u'Au/2 - "
                          "b'u times k plus e is the scene's, its "
                          "multipliers times k the contact forces (k and e: "
                          "lcp_force_unit and lcp_energy_offset in "
                          "summary.json). So is the plate's where its bending "
                          "rigidity is over 1e3 times from the paper's steel "
                          "plate's (lcp_force_unit; no offset).");
        prm.declare_entry("Write solution",
                          "false",
                          dealii::Patterns::Bool(),
                          "Write the solution of the LCP (u.txt and "
                          "lambda.txt, one number per line, 17 digits) in the "
                          "unknowns of the exported LCP, as the lcp scene "
                          "does; for comparing solutions to round-off (VTU "
                          "data are single precision).");
        prm.declare_entry("Print timings",
                          "true",
                          dealii::Patterns::Bool(),
                          "Print the table of wall time per stage at the end, "
                          "and begin each progress line with the seconds "
                          "since the run started (tests switch it off: their "
                          "output must not depend on time).");
        prm.declare_entry("Progress",
                          "true",
                          dealii::Patterns::Bool(),
                          "Print a line per solver iteration.");
      }
      prm.leave_subsection();
      solver.declare_parameters(prm);
      for (const auto &scene : SceneRegistry::all())
        scene.declare_parameters(prm);
    }

    int
    print_parameters(const std::string &format, std::ostream &out)
    {
      dealii::ParameterHandler prm;
      lcp::SolverParameters    solver;
      declare_parameters(prm, solver);
      if (format == "json")
        prm.print_parameters(out, dealii::ParameterHandler::JSON);
      else if (format == "prm")
        prm.print_parameters(out,
                             dealii::ParameterHandler::PRM |
                               dealii::ParameterHandler::KeepDeclarationOrder);
      else
        throw InputError("--print-parameters " + format +
                         ": unknown format; use prm or json");
      return 0;
    }

    // @p directory relative to the working directory (as git shows paths),
    // whatever folder the parameter file's relative paths started from.
    std::string
    shown(const std::filesystem::path &directory)
    {
      std::error_code             error;
      const std::filesystem::path relative =
        std::filesystem::relative(directory, error);
      return error || relative.empty() ? directory.string() : relative.string();
    }

    // True if @p parameter_file holds nothing but blanks and comments.
    bool
    sets_nothing(const std::string &parameter_file)
    {
      std::ifstream in(parameter_file);
      std::string   line;
      while (std::getline(in, line))
        {
          const auto first = line.find_first_not_of(" \t\r");
          if (first != std::string::npos && line[first] != '#')
            return false;
        }
      return true;
    }

    /**
     * Remove from @p directory the files an earlier run wrote there (the
     * scenes' outputs, grep write_vtu, write_pvd_record, write_vector and
     * write_summary, and the copy of the parameter file), so that they
     * cannot be taken for this run's: a masonry solution_000.vtu beside a
     * plate summary.json. Other files and all folders are kept, and so is
     * @p parameter_file if it lies there.
     */
    void
    remove_earlier_outputs(const std::filesystem::path &directory,
                           const std::string           &parameter_file)
    {
      const std::set<std::string> names = {"summary.json",
                                           "parameters.prm",
                                           "parameters.json",
                                           "parameters.xml",
                                           "u.txt",
                                           "lambda.txt",
                                           "active_set.txt",
                                           "lcp_A.mtx",
                                           "lcp_b.txt",
                                           "lcp_constraints.txt"};
      // The scenes' VTU, PVTU and PVD files by their names only (masonry:
      // solution.pvd, solution_000.vtu, solution_000.pvtu and its pieces
      // solution_000.R.vtu; plate: plate.* and nodes.*): the folder may hold
      // the user's own (Directory = . or a shared folder).
      const std::regex ours(
        "(solution|solution_[0-9]+(\\.[0-9]+)?|plate|nodes)\\.(vtu|pvtu|pvd)");
      for (const auto &entry : std::filesystem::directory_iterator(directory))
        {
          const std::filesystem::path &file = entry.path();
          std::error_code              error;
          // Also a file of ours a killed run left half written.
          if (!entry.is_regular_file() ||
              (names.count(name_when_written(file.filename().string())) == 0 &&
               !std::regex_match(file.filename().string(), ours)) ||
              std::filesystem::equivalent(file, parameter_file, error))
            continue;
          if (!std::filesystem::remove(file, error) && error)
            throw InputError("cannot remove '" + file.string() +
                             "', left by an earlier run: " + error.message());
        }
    }

    // The fix for a run that did not fit into memory: raising 'Memory
    // limit' where the limit, not the machine, was the bound.
    std::string
    memory_fix(const Scene &scene,
               const double limit,
               const double resident_before_scene)
    {
      // A limit the program used up before the scene built anything leaves
      // no problem small enough: then raising it is the only fix. (Used up
      // later, by the mesh or the matrices, a smaller problem fits too.)
      if (memory::limit_binds() && limit <= resident_before_scene)
        return "raise 'Memory limit': the program alone takes more than "
               "that before it builds its problem";
      return std::string(memory::limit_binds() ?
                           "raise 'Memory limit' (it is below the machine's "
                           "available memory) or " :
                           "") +
             (memory::address_space_limit_binds() ?
                "raise the address-space limit ('ulimit -v') or " :
                "") +
             "make the problem smaller (now " + scene.size_parameters() + ")";
    }

    /// 'Output/Run name' = @p setting, or the parameter file's name without
    /// extension where it is empty.
    std::string
    run_name_of(const std::string &parameter_file, const std::string &setting)
    {
      return setting.empty() ?
               std::filesystem::path(parameter_file).stem().string() :
               setting;
    }

    /// A run name that names a subdirectory of its own: no path in it.
    bool
    plain_name(const std::string &run_name)
    {
      return !run_name.empty() &&
             run_name.find_first_of("/\\") == std::string::npos &&
             run_name != "." && run_name != "..";
    }

    /// <Output/Directory>/<run name>, the directory taken from the parameter
    /// file's folder.
    std::filesystem::path
    run_folder(const std::string &parameter_file,
               const std::string &directory,
               const std::string &run_name)
    {
      return std::filesystem::path(
               directory.empty() ?
                 "output" :
                 resolve_relative_to(parameter_file, directory)) /
             run_name;
    }

    // A run that failed after its directory was made says so there, so
    // that the directory is not a puzzle.
    void
    write_error_summary(const RunContext  &context,
                        const std::string &scene,
                        const std::string &message)
    {
      JsonObject summary;
      summary.set("scene", scene)
        .set("run_name", context.run_name)
        .set("version", version::summary())
        .set("status", "error")
        .set("message", message)
        .set("converged", false);
      try
        {
          summary.write_file(
            (context.output_directory / "summary.json").string());
        }
      catch (const std::exception &)
        {
          // The message on stderr is what matters; it follows.
        }
    }

    /// The run's folder created, earlier outputs removed, the parameter
    /// file copied in.
    void
    prepare_output_directory(const std::filesystem::path &directory,
                             const std::string           &setting,
                             const std::string           &parameter_file)
    {
      std::error_code error;
      std::filesystem::create_directories(directory, error);
      if (error)
        throw InputError("parameter 'Output/Directory' = " + setting +
                         ": cannot create '" + directory.string() +
                         "': " + error.message());
      remove_earlier_outputs(directory, parameter_file);
      // The copy keeps the file's form (parameters.json for a JSON file),
      // which the parser tells by the ending. One left now is the file
      // being read (a rerun from the copy), not copied onto itself.
      const std::filesystem::path copy =
        directory / ("parameters." + parameter_file_kind(parameter_file));
      if (!std::filesystem::exists(copy))
        std::filesystem::copy_file(parameter_file, copy, error);
      if (error)
        throw InputError("cannot copy the parameter file into '" +
                         directory.string() + "': " + error.message());
    }

    /**
     * prepare_output_directory() by rank 0 alone, the other ranks waiting
     * for it (they may write into the folder): if it fails, rank 0 throws
     * its error and the others throw one that points to it, rather than
     * wait for a rank that has stopped.
     */
    void
    prepare_output_directory_on_rank_0(const std::filesystem::path &directory,
                                       const std::string           &setting,
                                       const std::string &parameter_file)
    {
      if (ranks::n_ranks() == 1)
        {
          prepare_output_directory(directory, setting, parameter_file);
          return;
        }
      int prepared = 1;
      try
        {
          if (ranks::this_rank() == 0)
            prepare_output_directory(directory, setting, parameter_file);
        }
      catch (...)
        {
          prepared = 0;
          MPI_Bcast(&prepared, 1, MPI_INT, 0, MPI_COMM_WORLD);
          throw;
        }
      MPI_Bcast(&prepared, 1, MPI_INT, 0, MPI_COMM_WORLD);
      if (!prepared)
        throw InputError("rank 0 could not prepare the output folder '" +
                         directory.string() + "' (its message says why)");
    }

    const std::string byte_order_mark = "\xEF\xBB\xBF";

    /**
     * Refuse a parameter file whose 'include' lines lead back to a file
     * already being read: deal.II's parser would recurse until the stack
     * overflows (a crash with no message). Refuse an included file that
     * starts with a UTF-8 byte-order mark: the parser, which opens included
     * files itself, takes the mark for part of the first line and refuses
     * that line, which looks well-formed in every editor (the main file's
     * mark is skipped, parse_parameter_file). Include paths are looked up as
     * the parser does, from the working directory, and else beside the
     * including file; one that exists nowhere is left to the parser's own
     * message.
     */
    void
    check_included_files(const std::filesystem::path        &file,
                         std::vector<std::filesystem::path> &reading)
    {
      const std::filesystem::path canonical =
        std::filesystem::weakly_canonical(file);
      if (std::find(reading.begin(), reading.end(), canonical) != reading.end())
        throw InputError("parameter file '" + reading.back().string() +
                         "' includes '" + file.string() +
                         "', which is already being read (an include "
                         "cycle): remove that include line");
      reading.push_back(canonical);
      std::ifstream in(file);
      std::string   line;
      if (reading.size() > 1 && std::getline(in, line) &&
          line.compare(0, byte_order_mark.size(), byte_order_mark) == 0)
        throw InputError("parameter file '" + file.string() +
                         "', included by '" +
                         reading[reading.size() - 2].string() +
                         "', starts with a UTF-8 byte-order mark, which "
                         "included files may not have: save it without one "
                         "(in most editors the encoding 'UTF-8', not 'UTF-8 "
                         "with BOM')");
      in.clear();
      in.seekg(0);
      while (std::getline(in, line))
        {
          const std::size_t start = line.find_first_not_of(" \t");
          if (start == std::string::npos ||
              line.compare(start, 8, "include ") != 0)
            continue;
          std::string name = line.substr(start + 8);
          name.erase(0, name.find_first_not_of(" \t"));
          name.erase(name.find_last_not_of(" \t\r") + 1);
          std::filesystem::path included = name;
          if (!std::filesystem::exists(included))
            included = file.parent_path() / name;
          if (std::filesystem::is_regular_file(included))
            check_included_files(included, reading);
        }
      reading.pop_back();
    }

    /**
     * ParameterHandler::parse_input, except that a UTF-8 byte-order mark at
     * the start of a .prm file (as some Windows editors save one) is skipped:
     * deal.II's parser would take it for part of the first line and refuse
     * that line, which looks well-formed in every editor.
     */
    void
    parse_parameter_file(dealii::ParameterHandler &prm,
                         const std::string        &parameter_file)
    {
      std::ifstream in(parameter_file, std::ios::binary);
      std::string   start(byte_order_mark.size(), '\0');
      const bool    marked =
        in.read(start.data(), static_cast<std::streamsize>(start.size())) &&
        start == byte_order_mark;
      const std::string kind = parameter_file_kind(parameter_file);
      if (kind != "prm" && kind != "json" && kind != "xml")
        throw InputError("parameter file '" + parameter_file +
                         "': its name must end in .prm, .json or .xml, "
                         "which tells the parser its form: rename it");
      check_structured_parameter_file(prm, parameter_file);
      try
        {
          if (!marked || kind != "prm")
            {
              prm.parse_input(parameter_file);
              return;
            }
          std::ostringstream rest;
          rest << in.rdbuf();
          std::istringstream text(rest.str());
          prm.parse_input(text, parameter_file);
        }
      catch (const dealii::ExceptionBase &error)
        {
          const std::string message =
            explain_parse_error(error, prm, parameter_file);
          if (message.empty())
            throw;
          throw InputError(message);
        }
    }

    /**
     * A setting in a subsection that only another scene reads (a plate's
     * 'Plate/Elements x' in a masonry file) would be ignored without a word
     * (a review): refused, as the scenes refuse settings that their own
     * options leave unread. Told by a value other than the default.
     */
    void
    refuse_other_scenes_settings(const dealii::ParameterHandler &prm,
                                 const std::string              &scene)
    {
      for (const SceneInfo &other : SceneRegistry::all())
        if (other.name != scene)
          for (const std::string &section :
               sections_declared_by(other.declare_parameters))
            {
              const auto [entry, value] = first_changed_entry(prm, section);
              if (!entry.empty())
                throw InputError("parameter '" + entry + "' = " + value +
                                 ": is read only by the " + other.name +
                                 " scene (now 'Scene = " + scene +
                                 "'): set 'Scene = " + other.name +
                                 "', or remove the line");
            }
    }

    int
    run(const std::string                                   &parameter_file,
        std::ostream                                        &out,
        const std::function<void(const std::string &, int)> &after_failed_run,
        std::string                                         &failure_line)
    {
      if (std::filesystem::is_directory(parameter_file))
        throw InputError("cannot read parameter file '" + parameter_file +
                         "': a directory, not a file");
      if (!std::filesystem::exists(parameter_file))
        throw InputError("cannot read parameter file '" + parameter_file +
                         "': no such file");
      if (!std::filesystem::is_regular_file(parameter_file))
        throw InputError("cannot read parameter file '" + parameter_file +
                         "': not a file");
      {
        std::vector<std::filesystem::path> reading;
        check_included_files(parameter_file, reading);
      }
      RunContext               context;
      dealii::ParameterHandler prm;
      declare_parameters(prm, context.solver);
      try
        {
          parse_parameter_file(prm, parameter_file);
        }
      catch (const InputError &error)
        {
          // A file the parser refused names its run's folder all the same
          // (read by the parser's rules): an earlier run's summary there is
          // not left saying 'converged' as if it were this run's.
          const std::string directory =
            value_in_file(parameter_file, "Output", "Directory", "");
          context.run_name = run_name_of(
            parameter_file,
            value_in_file(parameter_file, "Output", "Run name", ""));
          context.output_directory =
            run_folder(parameter_file, directory, context.run_name);
          if (ranks::this_rank() == 0 && plain_name(context.run_name) &&
              std::filesystem::exists(context.output_directory /
                                      "summary.json"))
            write_error_summary(
              context,
              value_in_file(parameter_file, "", "Scene", default_scene()),
              error.what());
          throw;
        }

      const SceneInfo &scene_info   = SceneRegistry::get(prm.get("Scene"));
      const double     memory_limit = 1e9 * prm.get_double("Memory limit");
      memory::set_limit(memory_limit);

      context.parameter_file = parameter_file;
      prm.enter_subsection("Output");
      const std::string directory = prm.get("Directory");
      context.run_name = run_name_of(parameter_file, prm.get("Run name"));
      check_parameter(plain_name(context.run_name),
                      "Output",
                      "Run name",
                      context.run_name,
                      "must be a plain name without '/' or '\\', and not "
                      "'.' or '..' (it names the run's subdirectory of "
                      "'Output/Directory'); to write elsewhere, set "
                      "'Output/Directory'");
      context.write_vtu      = prm.get_bool("Write VTU");
      context.export_lcp     = prm.get_bool("Export LCP");
      context.write_solution = prm.get_bool("Write solution");
      context.print_timings  = prm.get_bool("Print timings");
      const bool progress    = prm.get_bool("Progress");
      prm.leave_subsection();
      context.output_directory =
        run_folder(parameter_file, directory, context.run_name);
      // Rank 0 writes for all ranks, which compute the same answer; a scene
      // that writes its VTU in pieces has every rank write its own.
      context.writes_files = ranks::this_rank() == 0;

      std::unique_ptr<Scene> scene;
      try
        {
          refuse_other_scenes_settings(prm, scene_info.name);
          context.solver.parse_parameters(prm);
          scene = scene_info.create(prm);
        }
      catch (const std::exception &error)
        {
          // Bad input found before the run's folder is prepared leaves the
          // folder as it was, but not with an earlier run's summary saying
          // 'converged' as if it were this run's (a script reading it after
          // the failed run took the old success).
          if (context.writes_files &&
              std::filesystem::exists(context.output_directory /
                                      "summary.json"))
            write_error_summary(context,
                                scene_info.name,
                                one_line_message(error));
          throw;
        }
      if (std::isfinite(memory::address_space_limit()) &&
          !blas::prepare_for_address_space_limit())
        {
          const std::string refusal =
            "the address-space limit ('ulimit -v') of " +
            memory::format(memory::address_space_limit()) + " leaves " +
            memory::format(memory::address_space_limit() -
                           memory::address_space()) +
            " free, too little to start the run (the BLAS library's work "
            "buffer needs 136 MB); raise the limit";
          // The limit is a process's own: under mpirun it may bind on one
          // rank alone, which then has to end the others (they would wait
          // for it in their first collective call for ever).
          if (after_failed_run)
            after_failed_run("error: " + refusal, 1);
          throw InputError(refusal);
        }

      prepare_output_directory_on_rank_0(context.output_directory,
                                         directory,
                                         parameter_file);
      if (!context.writes_files)
        {
          context.export_lcp = context.write_solution = false;
          context.write_vtu =
            context.write_vtu && scene->writes_output_in_parallel();
        }

      // With timings on, each progress line says when it was written,
      // counted from the moment the timer's total starts.
      PrefixedLines       timed_progress(out, PrefixedLines::elapsed_seconds());
      dealii::TimerOutput timer(out,
                                dealii::TimerOutput::never,
                                dealii::TimerOutput::wall_times);
      context.out      = &out;
      context.progress = !progress             ? nullptr :
                         context.print_timings ? &timed_progress :
                                                 &out;
      context.timer    = &timer;

      // Valid, but surprising: say so.
      if (sets_nothing(parameter_file))
        out << "unilateral: note: '" << parameter_file
            << "' sets no parameter: running the default scene ("
            << scene_info.name << ") with every default; see unilateral "
            << "--print-parameters" << std::endl;
      out << "unilateral: scene " << scene_info.name << ", run '"
          << context.run_name << "'" << std::endl;
      lcp::Report  report;
      std::string  failure;
      bool         internal              = false;
      const double resident_before_scene = memory::resident();
      try
        {
          report = scene->run(context);
        }
      catch (const OutOfMemory &error)
        {
          failure = std::string(error.what()) +
                    (memory::address_space_limit_binds() ?
                       " (" + memory::address_space_in_use() + ")" :
                       "") +
                    "; " +
                    memory_fix(*scene, memory_limit, resident_before_scene);
        }
      catch (const std::bad_alloc &)
        {
          failure = "out of memory (an allocation failed, " +
                    (memory::address_space_limit_binds() ?
                       memory::address_space_in_use() :
                       memory::format(memory::available()) + " left") +
                    "); " +
                    memory_fix(*scene, memory_limit, resident_before_scene);
        }
      catch (const std::exception &error)
        {
          failure  = one_line_message(error);
          internal = is_internal(error);
          if (thread_refused(error))
            failure +=
              memory::address_space_limit_binds() ?
                "; raise the address-space limit ('ulimit -v'): every "
                "thread's stack takes some of it" :
                "; the system limits the threads of a process ('ulimit -u')";
        }
      if (!failure.empty())
        {
          if (internal)
            failure = "internal error (" + failure +
                      "): not a fault of the input; please report it with "
                      "the parameter file";
          if (context.writes_files)
            write_error_summary(context, scene_info.name, failure);
          if (after_failed_run)
            after_failed_run(internal ? failure : "error: " + failure,
                             internal ? 3 : 1);
          if (internal)
            throw InternalError(failure);
          throw InputError(failure);
        }
      out << "  results in " << shown(context.output_directory) << "/"
          << std::endl;
      if (context.print_timings)
        timer.print_summary();
      if (!report.converged())
        failure_line = scene->failure_description(report);
      return report.converged() ? 0 : 2;
    }
  } // namespace

  int
  run_application(
    int                                                  argc,
    char                                               **argv,
    std::ostream                                        &out,
    std::ostream                                        &err,
    const std::function<void(const std::string &, int)> &after_failed_run)
  {
    try
      {
        const std::string first = argc > 1 ? argv[1] : "";
        const bool        help  = first == "--help" || first == "-h";
        // --help and --version take nothing after them, --print-parameters
        // one format.
        const int most = help || first == "--version"  ? 2 :
                         first == "--print-parameters" ? 3 :
                                                         argc;
        if (argc > most)
          {
            std::string before = first;
            for (int k = 2; k < most; ++k)
              before += std::string(" ") + argv[k];
            throw InputError("unexpected argument '" + std::string(argv[most]) +
                             "' after " + before + "; see unilateral --help");
          }
        if (argc < 2 || help)
          {
            (argc < 2 ? err : out) << usage_text;
            return argc < 2 ? 1 : 0;
          }
        if (first == "--version")
          {
            out << version::describe() << "\n";
            return 0;
          }
        if (first == "--print-parameters")
          return print_parameters(argc > 2 ? argv[2] : "prm", out);
        if (first.rfind("-", 0) == 0)
          throw InputError("unknown option '" + first +
                           "'; see unilateral --help");
        if (argc > 2)
          throw InputError("expected one parameter file, got " +
                           std::to_string(argc - 1) +
                           " arguments; see unilateral --help");
        std::string failure_line;
        const int   code = run(first, out, after_failed_run, failure_line);
        if (!failure_line.empty())
          {
            out.flush();
            err << "unilateral: " << failure_line << std::endl;
          }
        return code;
      }
    catch (const InternalError &error)
      {
        out.flush();
        err << "unilateral: " << error.what() << std::endl;
        return 3;
      }
    catch (const std::exception &exception)
      {
        out.flush();
        err << "unilateral: error: " << one_line_message(exception)
            << std::endl;
        return 1;
      }
    catch (...)
      {
        err << "unilateral: error: unknown exception" << std::endl;
        return 1;
      }
  }
} // namespace unilateral
