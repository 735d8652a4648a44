#include <unilateral/base/input_error.h>
#include <unilateral/base/text.h>
#include <unilateral/scenes/masonry/supports.h>

#include <deal.II/base/function_parser.h>
#include <deal.II/base/utilities.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>

namespace unilateral::masonry
{
  std::string
  BoundaryNames::name(const dealii::types::boundary_id id) const
  {
    for (const auto &[name, value] : id_of_name)
      if (value == id)
        return name;
    return std::to_string(id);
  }

  namespace
  {
    const std::string section = "Masonry/Boundary conditions";

    /**
     * A FunctionParser of x, y (, z) with the constants, parsed and
     * evaluated once here so that a bad expression fails now, naming
     * @p parameter, and not in the middle of the assembly.
     */
    template <int dim>
    std::shared_ptr<const dealii::Function<dim>>
    parse_function(const std::vector<std::string> &components,
                   const ExpressionConstants      &constants,
                   const std::string              &parameter,
                   const std::string              &text)
    {
      auto function = std::make_shared<dealii::FunctionParser<dim>>(
        static_cast<unsigned int>(components.size()));
      const std::map<std::string, double> values = {{"g", constants.g},
                                                    {"H", constants.H},
                                                    {"s", constants.s},
                                                    {"pi", M_PI}};
      const std::string variables                = dim == 2 ? "x,y" : "x,y,z";
      // deal.II's FunctionParser also writes muparser's message to
      // std::cerr: silence it, the one line below says it.
      std::ostringstream silence;
      std::streambuf    *cerr_buffer = std::cerr.rdbuf(silence.rdbuf());
      try
        {
          function->initialize(variables, components, values);
          dealii::Vector<double> probe(components.size());
          function->vector_value(dealii::Point<dim>(), probe);
          std::cerr.rdbuf(cerr_buffer);
        }
      catch (const std::exception &error)
        {
          std::cerr.rdbuf(cerr_buffer);
          // muparser's own message, without deal.II's banner and trace.
          std::string       reason = error.what();
          const std::size_t at     = reason.find("The parser said:");
          if (at != std::string::npos)
            reason = reason.substr(at + 16);
          const std::size_t trace = reason.find("Stacktrace");
          if (trace != std::string::npos)
            reason = reason.substr(0, trace);
          reason = dealii::Utilities::trim(reason);
          for (char &c : reason)
            if (c == '\n')
              c = ' ';
          check_parameter(false,
                          section,
                          parameter,
                          text,
                          "is not an expression of " + variables +
                            " and the constants g, H, s, pi (" + reason + ")");
        }
      return function;
    }

    /// Whether @p component is the number 0 ('0', '0.0', '-0', '0e5');
    /// an expression is not, even one that is zero everywhere.
    bool
    is_zero(const std::string &component)
    {
      double value = 0;
      return parse_number(component, value) && value == 0;
    }

    /// "a; b; c" as dim expressions; all-zero vectors may have fewer.
    std::vector<std::string>
    vector_components(const std::string &text,
                      const unsigned int dim,
                      const std::string &parameter)
    {
      std::vector<std::string> components =
        dealii::Utilities::split_string_list(text, ';');
      const bool zero =
        std::all_of(components.begin(), components.end(), is_zero);
      if (zero && components.size() <= 3)
        components.assign(dim, "0");
      check_parameter(components.size() == dim,
                      section,
                      parameter,
                      text,
                      "has " + std::to_string(components.size()) +
                        " components; give " + std::to_string(dim) +
                        " separated by ';' (x; y" + (dim == 3 ? "; z)" : ")"));
      return components;
    }

    dealii::types::boundary_id
    boundary_id(const BoundarySelection &selection,
                const BoundaryNames     &names,
                const std::string       &parameter)
    {
      const auto named              = names.id_of_name.find(selection.boundary);
      dealii::types::boundary_id id = 0;
      bool                       found = named != names.id_of_name.end();
      if (found)
        id = named->second;
      else
        {
          char      *end    = nullptr;
          const long number = std::strtol(selection.boundary.c_str(), &end, 10);
          found = end != selection.boundary.c_str() && *end == '\0' &&
                  number >= 0 && number < 255;
          id = static_cast<dealii::types::boundary_id>(number);
          // 0 without a name is what deal.II gives every face no tag
          // names, the joints between blocks among them: not a support.
          if (found && id == 0 && names.name(0) == "0")
            found = false;
        }
      if (found && names.optional.count(selection.boundary) > 0)
        return id;
      if (!found || names.ids_on_boundary.count(id) == 0)
        {
          std::ostringstream       known;
          std::vector<std::string> known_names;
          for (const auto &[name, value] : names.id_of_name)
            if (names.ids_on_boundary.count(value))
              {
                known << (known.tellp() > 0 ? ", " : "") << name;
                known_names.push_back(name);
              }
          const std::string nearest =
            nearest_name(selection.boundary, known_names);
          for (const auto value : names.ids_on_boundary)
            if (value != 0 && names.name(value) == std::to_string(value))
              known << (known.tellp() > 0 ? ", " : "") << value;
          check_parameter(false,
                          section,
                          parameter,
                          selection.boundary,
                          "is not a boundary of " + names.source +
                            " (its named boundaries: " +
                            (known.tellp() > 0 ? known.str() : "none") + "); " +
                            (nearest.empty() ?
                               names.fix :
                               "did you mean '" + nearest + "'?"));
        }
      return id;
    }
  } // namespace

  template <int dim>
  bool
  Supports<dim>::acts_at(
    const Support<dim>                    &support,
    const dealii::Point<dim>              &node,
    const std::vector<dealii::Point<dim>> &face_vertices) const
  {
    if (support.region == nullptr)
      return true;
    const auto inside = [&](const dealii::Point<dim> &p) {
      return support.region->value(p) > 0.5;
    };
    if (inside(node))
      return true;
    dealii::Point<dim> centre;
    for (const auto &v : face_vertices)
      centre += v / static_cast<double>(face_vertices.size());
    constexpr double step = 1e-6;
    if (inside(node + step * (centre - node)))
      return true;
    for (const auto &v : face_vertices)
      if (v.distance(node) > 0 && inside(node + step * (v - node)))
        return true;
    return false;
  }

  template <int dim>
  std::vector<const Support<dim> *>
  Supports<dim>::on_boundary(const dealii::types::boundary_id boundary) const
  {
    std::vector<const Support<dim> *> result;
    for (const Support<dim> &support : list)
      if (support.boundary == boundary)
        result.push_back(&support);
    return result;
  }

  template <int dim>
  Supports<dim>
  make_supports(const BoundaryParameters  &parameters,
                const BoundaryNames       &names,
                const ExpressionConstants &constants)
  {
    using Kind = typename Support<dim>::Kind;
    Supports<dim> supports;
    const struct
    {
      const std::vector<BoundarySelection> &selections;
      Kind                                  kind;
      bool                                  prescribed;
      const char                           *parameter;
    } groups[] = {
      {parameters.fixed, Kind::held, false, "Fixed"},
      {parameters.prescribed,
       Kind::held,
       true,
       "Prescribed displacement boundaries"},
      {parameters.normal_displacement_zero,
       Kind::normal_zero,
       false,
       "Normal displacement zero"},
      {parameters.signorini, Kind::signorini, false, "Signorini"},
      {parameters.traction, Kind::traction, false, "Traction boundaries"}};
    for (const auto &group : groups)
      for (const BoundarySelection &selection : group.selections)
        {
          Support<dim> support;
          support.kind       = group.kind;
          support.prescribed = group.prescribed;
          support.name       = selection.boundary;
          support.description =
            std::string("'") + group.parameter + "' = '" + selection.boundary +
            (selection.region.empty() ? "" : " where " + selection.region) +
            "'";
          support.boundary = boundary_id(selection, names, group.parameter);
          if (!selection.region.empty())
            support.region =
              parse_function<dim>({selection.region},
                                  constants,
                                  group.parameter,
                                  selection.boundary + " where " +
                                    selection.region);
          supports.list.push_back(support);
        }
    supports.gap = parse_function<dim>({parameters.gap},
                                       constants,
                                       "Signorini gap",
                                       parameters.gap);
    const std::vector<std::string> prescribed =
      vector_components(parameters.prescribed_displacement,
                        dim,
                        "Prescribed displacement");
    supports.displacement =
      parse_function<dim>(prescribed,
                          constants,
                          "Prescribed displacement",
                          parameters.prescribed_displacement);
    const std::vector<std::string> traction =
      vector_components(parameters.traction_value, dim, "Traction");
    supports.traction = parse_function<dim>(traction,
                                            constants,
                                            "Traction",
                                            parameters.traction_value);
    supports.zero_traction =
      std::all_of(traction.begin(), traction.end(), is_zero);
    // Values that no boundary would take are refused rather than dropped
    // (a review: a traction of '0; -5' with no 'Traction boundaries' left
    // the wall unloaded, exit 0).
    check_parameter(!parameters.traction.empty() || supports.zero_traction,
                    section,
                    "Traction",
                    parameters.traction_value,
                    "loads no boundary ('Traction boundaries' is empty): "
                    "name the boundaries it loads, or set it to 0");
    check_parameter(!parameters.prescribed.empty() ||
                      std::all_of(prescribed.begin(),
                                  prescribed.end(),
                                  is_zero),
                    section,
                    "Prescribed displacement",
                    parameters.prescribed_displacement,
                    "moves no boundary ('Prescribed displacement "
                    "boundaries' is empty): name the boundaries it moves, or "
                    "set it to 0");
    for (unsigned int d = 0; d < dim; ++d)
      supports.gravity[d] =
        parameters.gravity * parameters.gravity_direction[d];
    return supports;
  }

  template struct Supports<2>;
  template struct Supports<3>;
  template Supports<2>
  make_supports<2>(const BoundaryParameters &,
                   const BoundaryNames &,
                   const ExpressionConstants &);
  template Supports<3>
  make_supports<3>(const BoundaryParameters &,
                   const BoundaryNames &,
                   const ExpressionConstants &);
} // namespace unilateral::masonry
