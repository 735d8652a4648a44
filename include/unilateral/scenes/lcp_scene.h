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
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    explicit LcpScene(dealii::ParameterHandler &prm);

    lcp::Report
    run(RunContext &context) override;

    std::string
    size_parameters() const override
    {
      return "the LCP in 'LCP/Matrix file' = " + matrix_file;
    }

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
