#pragma once

#include <unilateral/scenes/scene.h>

#include <string>

namespace unilateral
{
  /**
   * The "lcp" scene: an LCP read from files (see lcp/io.h for the format),
   * solved with any method; writes u.txt, lambda.txt and active_set.txt
   * (1-based indices) beside summary.json. Relative file names are taken
   * from the parameter file's directory.
   */
  class LcpScene : public Scene
  {
  public:
    static constexpr const char *registered_name = "lcp";

    static void
    declare_parameters(dealii::ParameterHandler &prm);

    explicit LcpScene(dealii::ParameterHandler &prm);

    std::string
    size_parameters() const override
    {
      return "'LCP/Matrix file' = " + matrix_file;
    }

  protected:
    /// Read the LCP from its files.
    void
    assemble_system(RunContext &context) override;

    /// u.txt, lambda.txt and active_set.txt: the scene's result, written
    /// whatever 'Output/Write VTU' says.
    void
    postprocess(const RunContext &context, lcp::Report &report) override;

  private:
    std::string matrix_file;
    std::string rhs_file;
    std::string constraints_file;
  };

  /// @p file_name as given if absolute, else relative to the directory of
  /// @p parameter_file.
  std::string
  resolve_relative_to(const std::string &parameter_file,
                      const std::string &file_name);
} // namespace unilateral
