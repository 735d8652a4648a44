#pragma once

#include <unilateral/scenes/masonry/supports.h>

#include <string>
#include <vector>

namespace dealii
{
  template <int dim, int spacedim>
  class Triangulation;
}

namespace unilateral::masonry
{
  /// What a mesh file says beyond the triangulation.
  struct MeshFileBlocks
  {
    /// The physical tag of each block's cells, as its name if the file
    /// names it, else its number.
    std::vector<std::string> tag_of_block;
    /// The physical tags of the blocks by number too ("3"), for matching a
    /// material's tag given as a number.
    std::vector<unsigned int> tag_number_of_block;
    /// The boundaries: physical names of lines (2D) or surfaces (3D).
    BoundaryNames boundaries;
    /// Whether the cells are simplices (triangles, tetrahedra).
    bool simplex = false;
  };

  /**
   * Read the blocks of a Gmsh file (formats 2.2 and 4.1, ASCII) into
   * @p triangulation, through deal.II's GridIn: quadrilaterals or triangles
   * in 2D (the z coordinates must be 0), hexahedra or tetrahedra in 3D. A
   * block is a connected set of cells (sharing vertices) of one geometric
   * entity and one physical tag; vertices that blocks share in the file
   * are split, so that every block is a connected component of its own
   * (material_id = block index, numbered in the order of the blocks' first
   * cells). Boundary faces keep the ids of the file's physical lines or
   * surfaces (0 where the file names none).
   *
   * Throws InputError with one line naming the file for: a file that
   * cannot be read, an unsupported format or element type, a cell that is
   * inverted or has no volume, no cells of dimension @p dim.
   */
  template <int dim>
  MeshFileBlocks
  read_mesh_file(const std::string               &file_name,
                 dealii::Triangulation<dim, dim> &triangulation);
} // namespace unilateral::masonry
