#pragma once

#include <string>
#include <vector>

/**
 * The masonry layout: which rectangular blocks the wall is made of. Everything
 * after the layout (mesh, contact detection, change of variables, assembly)
 * works for any list of axis-aligned rectangles; the three bonds of
 * Ainsworth & Mihai, Section 5, are just three ways of making the list.
 */
namespace unilateral::masonry
{
  /// One block: the rectangle [x0, x1] x [y0, y1].
  struct Block
  {
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;

    double
    width() const
    {
      return x1 - x0;
    }

    double
    height() const
    {
      return y1 - y0;
    }
  };

  struct BoundingBox
  {
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  };

  struct Layout
  {
    /// What the layout is ("stack bond", ...), for messages and summaries.
    std::string name;
    /// H, the course (row) height: the unit of the mesh size h = H / 2^r and
    /// of the gap g.
    double             course_height = 1;
    std::vector<Block> blocks;

    BoundingBox
    bounding_box() const;

    /// The course of every block: rank of its lower edge y0 among the
    /// distinct lower edges (0 = bottom course). Used by material rules.
    std::vector<unsigned int>
    courses() const;
  };

  /// The geometries of the paper on the unit square, H = 1/m.
  enum class Bond
  {
    stack,   ///< H x H blocks
    running, ///< 2H x H bricks, rows shifted by H, half bricks at the ends
    laminae  ///< 1 x H strips
  };

  /// "stack bond|running bond|laminae", for Patterns::Selection.
  std::string
  bond_names();

  /// Throws InputError on an unknown name.
  Bond
  parse_bond(const std::string &name);

  std::string
  to_string(Bond bond);

  /// Stack bond: m x m squares of size H = 1/m.
  Layout
  stack_bond(unsigned int m);

  /// Running bond: the base row starts with a full brick at x = 0, each next
  /// row is shifted by H; bricks cut by x = 0 or x = 1 become half bricks.
  Layout
  running_bond(unsigned int m);

  /// Laminae: m strips 1 x H.
  Layout
  laminae(unsigned int m);

  Layout
  make_layout(Bond bond, unsigned int m);

  /**
   * Check that @p layout is a wall we can mesh: at least one block, every
   * block of positive width and height, no two blocks overlapping (touching
   * along edges or at corners is what masonry does). Throws InputError naming
   * the offending blocks.
   */
  void
  validate(const Layout &layout);
} // namespace unilateral::masonry
