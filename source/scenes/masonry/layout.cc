#include <unilateral/base/input_error.h>
#include <unilateral/scenes/masonry/layout.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace unilateral::masonry
{
  BoundingBox
  Layout::bounding_box() const
  {
    BoundingBox box;
    if (blocks.empty())
      return box;
    box = {blocks[0].x0, blocks[0].y0, blocks[0].x1, blocks[0].y1};
    for (const Block &block : blocks)
      {
        box.x0 = std::min(box.x0, block.x0);
        box.y0 = std::min(box.y0, block.y0);
        box.x1 = std::max(box.x1, block.x1);
        box.y1 = std::max(box.y1, block.y1);
      }
    return box;
  }

  std::vector<unsigned int>
  Layout::courses() const
  {
    // Lower edges closer than a small fraction of H belong to the same course.
    const double        tolerance = 1e-8 * course_height;
    std::vector<double> levels;
    levels.reserve(blocks.size());
    for (const Block &block : blocks)
      levels.push_back(block.y0);
    std::sort(levels.begin(), levels.end());
    std::vector<double> distinct;
    for (const double level : levels)
      if (distinct.empty() || level - distinct.back() > tolerance)
        distinct.push_back(level);

    std::vector<unsigned int> result(blocks.size());
    for (std::size_t b = 0; b < blocks.size(); ++b)
      {
        const auto above = std::upper_bound(distinct.begin(),
                                            distinct.end(),
                                            blocks[b].y0 + tolerance);
        result[b] = static_cast<unsigned int>(above - distinct.begin()) - 1;
      }
    return result;
  }

  std::string
  bond_names()
  {
    return "stack bond|running bond|laminae";
  }

  Bond
  parse_bond(const std::string &name)
  {
    if (name == "stack bond")
      return Bond::stack;
    if (name == "running bond")
      return Bond::running;
    if (name == "laminae")
      return Bond::laminae;
    throw InputError("parameter 'Masonry/Geometry' = " + name +
                     ": unknown geometry; choose one of " + bond_names());
  }

  std::string
  to_string(const Bond bond)
  {
    switch (bond)
      {
        case Bond::stack:
          return "stack bond";
        case Bond::running:
          return "running bond";
        case Bond::laminae:
          return "laminae";
      }
    return "";
  }

  namespace
  {
    // Coordinates are k / m for integer k, computed the same way for every
    // block, so edges shared by two blocks agree to the last bit.
    double
    grid(const unsigned int k, const unsigned int m)
    {
      return static_cast<double>(k) / static_cast<double>(m);
    }
  } // namespace

  Layout
  stack_bond(const unsigned int m)
  {
    Layout layout;
    layout.name          = "stack bond";
    layout.course_height = grid(1, m);
    layout.blocks.reserve(static_cast<std::size_t>(m) * m);
    for (unsigned int j = 0; j < m; ++j)
      for (unsigned int i = 0; i < m; ++i)
        layout.blocks.push_back(
          {grid(i, m), grid(j, m), grid(i + 1, m), grid(j + 1, m)});
    return layout;
  }

  Layout
  running_bond(const unsigned int m)
  {
    Layout layout;
    layout.name          = "running bond";
    layout.course_height = grid(1, m);
    for (unsigned int j = 0; j < m; ++j)
      {
        // Brick edges in units of H: 0, 2, 4, ... in even rows and
        // 0, 1, 3, 5, ... in odd rows (shifted by H), always ending at m.
        std::vector<unsigned int> edges{0};
        for (unsigned int k = (j % 2 == 0) ? 2 : 1; k < m; k += 2)
          edges.push_back(k);
        edges.push_back(m);
        for (std::size_t k = 0; k + 1 < edges.size(); ++k)
          layout.blocks.push_back({grid(edges[k], m),
                                   grid(j, m),
                                   grid(edges[k + 1], m),
                                   grid(j + 1, m)});
      }
    return layout;
  }

  Layout
  laminae(const unsigned int m)
  {
    Layout layout;
    layout.name          = "laminae";
    layout.course_height = grid(1, m);
    for (unsigned int j = 0; j < m; ++j)
      layout.blocks.push_back({0.0, grid(j, m), 1.0, grid(j + 1, m)});
    return layout;
  }

  Layout
  make_layout(const Bond bond, const unsigned int m)
  {
    check_parameter(m >= 1,
                    "Masonry",
                    "Blocks per side",
                    m,
                    "must be an integer >= 1 (the block height is H = 1/m)");
    switch (bond)
      {
        case Bond::stack:
          return stack_bond(m);
        case Bond::running:
          return running_bond(m);
        case Bond::laminae:
          return laminae(m);
      }
    return {};
  }

  void
  validate(const Layout &layout)
  {
    if (layout.blocks.empty())
      throw InputError("the masonry layout '" + layout.name +
                       "' has no blocks");
    double smallest = std::numeric_limits<double>::max();
    for (std::size_t b = 0; b < layout.blocks.size(); ++b)
      {
        const Block &block = layout.blocks[b];
        if (!(block.width() > 0) || !(block.height() > 0) ||
            !std::isfinite(block.width()) || !std::isfinite(block.height()))
          {
            std::ostringstream message;
            message << "block " << b << " of the masonry layout '"
                    << layout.name << "' is [" << block.x0 << ", " << block.x1
                    << "] x [" << block.y0 << ", " << block.y1
                    << "]: a block needs positive width and height";
            throw InputError(message.str());
          }
        smallest = std::min({smallest, block.width(), block.height()});
      }

    // Overlap test on a bucket grid: each block is registered in the buckets
    // its interior meets, and only blocks sharing a bucket are compared, so
    // the cost is linear in the number of blocks for walls of similar blocks.
    const BoundingBox box    = layout.bounding_box();
    const double      width  = box.x1 - box.x0;
    const double      height = box.y1 - box.y0;
    const double      bucket =
      std::max(smallest,
               std::sqrt(width * height / (4.0 * layout.blocks.size())));
    const auto nx =
      static_cast<std::size_t>(std::max(1.0, std::ceil(width / bucket)));
    const auto ny =
      static_cast<std::size_t>(std::max(1.0, std::ceil(height / bucket)));
    const double touch = 1e-10 * smallest;

    auto range = [&](const double      a,
                     const double      b,
                     const double      origin,
                     const std::size_t n) {
      auto clamp = [n](const double v) {
        return static_cast<std::size_t>(
          std::min<double>(static_cast<double>(n - 1), std::max(0.0, v)));
      };
      return std::pair{clamp(std::floor((a + touch - origin) / bucket)),
                       clamp(std::floor((b - touch - origin) / bucket))};
    };

    std::vector<std::vector<unsigned int>> buckets(nx * ny);
    for (std::size_t b = 0; b < layout.blocks.size(); ++b)
      {
        const Block &block  = layout.blocks[b];
        const auto [i0, i1] = range(block.x0, block.x1, box.x0, nx);
        const auto [j0, j1] = range(block.y0, block.y1, box.y0, ny);
        for (std::size_t j = j0; j <= j1; ++j)
          for (std::size_t i = i0; i <= i1; ++i)
            buckets[j * nx + i].push_back(static_cast<unsigned int>(b));
      }

    for (const auto &members : buckets)
      for (std::size_t p = 0; p < members.size(); ++p)
        for (std::size_t q = p + 1; q < members.size(); ++q)
          {
            const Block &a = layout.blocks[members[p]];
            const Block &b = layout.blocks[members[q]];
            const double overlap_x =
              std::min(a.x1, b.x1) - std::max(a.x0, b.x0);
            const double overlap_y =
              std::min(a.y1, b.y1) - std::max(a.y0, b.y0);
            if (overlap_x > touch && overlap_y > touch)
              {
                std::ostringstream message;
                message << "blocks " << members[p] << " and " << members[q]
                        << " of the masonry layout '" << layout.name
                        << "' overlap: [" << a.x0 << ", " << a.x1 << "] x ["
                        << a.y0 << ", " << a.y1 << "] and [" << b.x0 << ", "
                        << b.x1 << "] x [" << b.y0 << ", " << b.y1
                        << "]; blocks may only touch along edges or corners";
                throw InputError(message.str());
              }
          }
  }
} // namespace unilateral::masonry
