// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors

#include <fdem/geometry/cases/block_on_plane.h>
#include <fdem/geometry/structured_grid.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/numbers.h>
#include <deal.II/physics/transformations.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace fdem
{
  namespace geometry
  {
    namespace
    {
      /** The thicknesses normal to the plane, the same in 2D and 3D. */
      void
      declare_heights(ParameterHandler &prm)
      {
        prm.declare_entry("Block height",
                          "5",
                          Patterns::Double(0),
                          "Height of the block normal to the plane (m).");
        prm.declare_entry("Foundation thickness",
                          "5",
                          Patterns::Double(0),
                          "Thickness of the foundation slab normal to the "
                          "plane (m).");
      }



      /** The entries that only the 2D case (Inclined block) has. */
      void
      declare_parameters_2d(ParameterHandler &prm)
      {
        prm.declare_entry("Inclination",
                          "30",
                          Patterns::Double(0, 89),
                          "Angle of the plane with the x axis, rising to "
                          "the right (degrees).");
        prm.declare_entry("Block length",
                          "10",
                          Patterns::Double(0),
                          "Length of the block along the plane (m).");
        declare_heights(prm);
        prm.declare_entry("Foundation overhang",
                          "5",
                          Patterns::Double(0),
                          "Length the foundation extends beyond each end "
                          "of the block (m).");
        prm.declare_entry("Elements along length",
                          "10",
                          Patterns::Integer(1),
                          "Number of elements of the block along the "
                          "plane; the foundation gets elements of that size.");
        prm.declare_entry("Elements across height",
                          "5",
                          Patterns::Integer(1),
                          "Number of elements of the block normal to the "
                          "plane; the foundation gets elements of that size.");
        case_input::declare_element_shape_2d(
          prm,
          "quadrilaterals (FE_Q elements), or "
          "triangles (FE_SimplexP), two per quadrilateral of the same "
          "structured grid.");
      }



      /** The entries that only the 3D case (Block on plane) has. */
      void
      declare_parameters_3d(ParameterHandler &prm)
      {
        prm.declare_entry(
          "Dip",
          "30",
          Patterns::Double(0, 90),
          "Dip psi of the plane, below the horizontal (degrees). 3D, x = "
          "east, y = north, z = up: the plane passes through the origin "
          "with the upward unit normal n = (sin psi sin alpha, sin psi cos "
          "alpha, cos psi).");
        prm.declare_entry(
          "Dip direction",
          "120",
          Patterns::Double(0, 360),
          "Dip direction alpha of the plane: azimuth of its line of "
          "steepest descent, clockwise from north (degrees). The block's "
          "length runs down the dip from the origin, its width is centred "
          "on the origin along the strike.");
        prm.declare_entry("Block length",
                          "10",
                          Patterns::Double(0),
                          "Length of the block down the dip (m).");
        prm.declare_entry("Block width",
                          "6",
                          Patterns::Double(0),
                          "Width of the block along the strike (m).");
        declare_heights(prm);
        prm.declare_entry("Foundation overhang",
                          "3",
                          Patterns::Double(0),
                          "Length the foundation extends beyond the block "
                          "on each of its four sides (m).");
        prm.declare_entry("Elements along length",
                          "10",
                          Patterns::Integer(1),
                          "Number of elements of the block down the dip; "
                          "the foundation gets elements of that length.");
        prm.declare_entry("Elements along width",
                          "6",
                          Patterns::Integer(1),
                          "Number of elements of the block along the "
                          "strike; the foundation gets elements of that "
                          "width.");
        prm.declare_entry("Elements across height",
                          "5",
                          Patterns::Integer(1),
                          "Number of elements of the block normal to the "
                          "plane; the foundation gets elements of that "
                          "height.");
      }



      /**
       * The number of elements of about the size @p size across
       * @p distance, at least one.
       */
      unsigned int
      n_elements(const double distance, const double size)
      {
        return static_cast<unsigned int>(
          std::max<long>(1, std::lround(distance / size)));
      }



      /**
       * Coordinates of the grid lines from breaks[0] to breaks.back(), with
       * n_segments[i] equal segments between breaks[i] and breaks[i + 1].
       */
      std::vector<double>
      grid_lines(const std::vector<double>       &breaks,
                 const std::vector<unsigned int> &n_segments)
      {
        std::vector<double> ticks = {breaks[0]};
        for (unsigned int i = 0; i < n_segments.size(); ++i)
          for (unsigned int j = 1; j <= n_segments[i]; ++j)
            ticks.push_back((j == n_segments[i]) ?
                              breaks[i + 1] :
                              breaks[i] + (breaks[i + 1] - breaks[i]) * j /
                                            n_segments[i]);
        return ticks;
      }



      /**
       * Every quadrilateral of @p mesh split into two triangles by its
       * diagonal from vertex 1 to vertex 2 (lexicographic numbering), both
       * positively oriented; the face groups are unchanged.
       * Hand-written: GridGenerator::convert_hypercube_to_simplex_mesh
       * makes eight triangles per quadrilateral, not the two that the
       * Element shape entry promises.
       */
      void
      split_into_triangles(MeshDescription<2> &mesh)
      {
        std::vector<CellData<2>> triangles;
        for (const CellData<2> &quadrilateral : mesh.cells)
          for (const std::array<unsigned int, 3> &corners :
               {std::array<unsigned int, 3>{{0, 1, 2}},
                std::array<unsigned int, 3>{{1, 3, 2}}})
            {
              CellData<2> triangle(3);
              for (unsigned int v = 0; v < 3; ++v)
                triangle.vertices[v] = quadrilateral.vertices[corners[v]];
              triangle.material_id = quadrilateral.material_id;
              triangles.push_back(triangle);
            }
        mesh.cells = triangles;
      }
    } // namespace



    template <>
    Tensor<2, 2>
    BlockOnPlane<2>::rotation() const
    {
      return Physics::Transformations::Rotations::rotation_matrix_2d(
        inclination * numbers::PI / 180);
    }



    // Built from the plane's own unit vectors rather than by
    // Physics::Transformations::Rotations::rotation_matrix_3d: the frame is
    // given by its axes, not by an axis and an angle.
    template <>
    Tensor<2, 3>
    BlockOnPlane<3>::rotation() const
    {
      const Tensor<1, 3> down_dip = plane.down_dip_direction();
      const Tensor<1, 3> normal   = plane.upward_normal();
      const Tensor<1, 3> strike   = cross_product_3d(normal, down_dip);
      Tensor<2, 3>       rotation;
      for (unsigned int i = 0; i < 3; ++i)
        {
          rotation[i][0] = down_dip[i];
          rotation[i][1] = strike[i];
          rotation[i][2] = normal[i];
        }
      return rotation;
    }



    template <int dim>
    std::string
    BlockOnPlane<dim>::subsection_name()
    {
      return (dim == 2) ? "Inclined block" : "Block on plane";
    }



    template <int dim>
    void
    BlockOnPlane<dim>::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection(subsection_name());
      if (dim == 2)
        declare_parameters_2d(prm);
      else
        declare_parameters_3d(prm);
      prm.leave_subsection();
    }



    template <int dim>
    void
    BlockOnPlane<dim>::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection(subsection_name());
      {
        if constexpr (dim == 2)
          {
            this->inclination   = prm.get_double("Inclination");
            this->element_shape = case_input::parse_element_shape(prm);
          }
        else
          {
            this->plane.dip           = prm.get_double("Dip");
            this->plane.dip_direction = prm.get_double("Dip direction");
            this->block_width         = prm.get_double("Block width");
            this->n_elements_along_width =
              prm.get_integer("Elements along width");
          }
        block_length             = prm.get_double("Block length");
        block_height             = prm.get_double("Block height");
        foundation_thickness     = prm.get_double("Foundation thickness");
        foundation_overhang      = prm.get_double("Foundation overhang");
        n_elements_along_length  = prm.get_integer("Elements along length");
        n_elements_across_height = prm.get_integer("Elements across height");
      }
      prm.leave_subsection();
    }



    template <int dim>
    void
    BlockOnPlane<dim>::validate() const
    {
      const std::string path = "Geometry/" + subsection_name() + "/";
      if constexpr (dim == 2)
        case_input::require(block_length > 0 && block_height > 0,
                            path + "Block length and height: must be "
                                   "positive.");
      else
        case_input::require(block_length > 0 && this->block_width > 0 &&
                              block_height > 0,
                            path + "Block length, width and height: must "
                                   "be positive.");
      case_input::require(foundation_thickness > 0 && foundation_overhang > 0,
                          path + "Foundation thickness and overhang: must "
                                 "be positive.");
    }



    template <int dim>
    MeshDescription<dim>
    make_block_on_plane_mesh(const BlockOnPlane<dim> &block_on_plane)
    {
      const auto        &b         = block_on_plane;
      const double       overhang  = b.foundation_overhang;
      const double       thickness = b.foundation_thickness;
      const double       height    = b.block_height;
      const unsigned int n_height  = b.n_elements_across_height;

      // Along the plane: the block's extent [begin, end] and its number of
      // elements in each direction, and the foundation's grid lines there
      // (elements of the block's size, split at the block's edges).
      std::array<double, dim - 1>       begin, end;
      std::array<unsigned int, dim - 1> n_block, n_overhang;
      begin[0]   = 0;
      end[0]     = b.block_length;
      n_block[0] = b.n_elements_along_length;
      if constexpr (dim == 3)
        {
          begin[1]   = -b.block_width / 2;
          end[1]     = b.block_width / 2;
          n_block[1] = b.n_elements_along_width;
        }
      std::array<std::vector<double>, dim> lines;
      for (unsigned int d = 0; d + 1 < dim; ++d)
        {
          n_overhang[d] =
            n_elements(overhang, (end[d] - begin[d]) / n_block[d]);
          lines[d] = grid_lines(
            {begin[d] - overhang, begin[d], end[d], end[d] + overhang},
            {n_overhang[d], n_block[d], n_overhang[d]});
        }
      // Normal to the plane: the foundation's lines, then the block's.
      const unsigned int n_thickness = n_elements(thickness, height / n_height);
      lines[dim - 1] = grid_lines({-thickness, 0}, {n_thickness});
      const std::vector<double> normal_block_lines =
        grid_lines({0, height}, {n_height});

      MeshDescription<dim> mesh;
      mesh.source           = "Geometry/" + b.subsection_name();
      mesh.block_names      = {"block", "foundation"};
      mesh.face_group_names = {"sliding surface",
                               "block surface",
                               "foundation surface",
                               "foundation base",
                               "foundation ends"};
      enum Group
      {
        sliding_surface,
        block_surface,
        foundation_surface,
        foundation_base,
        foundation_ends
      };
      const Tensor<2, dim> rotation   = b.rotation();
      const auto           add_vertex = [&](const Tensor<1, dim> &frame_point) {
        mesh.vertices.emplace_back(rotation * frame_point);
        return static_cast<unsigned int>(mesh.vertices.size() - 1);
      };

      // Foundation vertices in lexicographic order (the first index
      // fastest), then the block's above its top.
      std::array<unsigned int, dim> n_foundation_points;
      unsigned int                  n_points = 1;
      for (unsigned int d = 0; d < dim; ++d)
        n_points *= (n_foundation_points[d] = lines[d].size());
      std::vector<unsigned int> foundation_vertex;
      for (unsigned int p = 0; p < n_points; ++p)
        {
          Tensor<1, dim> frame_point;
          for (unsigned int d = 0, rest = p; d < dim;
               rest /= n_foundation_points[d], ++d)
            frame_point[d] = lines[d][rest % n_foundation_points[d]];
          foundation_vertex.push_back(add_vertex(frame_point));
        }
      const auto foundation_index = [&](const auto... indices) {
        const std::array<unsigned int, dim> ijk  = {{indices...}};
        unsigned int                        flat = 0;
        for (unsigned int d = dim; d-- > 0;)
          flat = flat * n_foundation_points[d] + ijk[d];
        return foundation_vertex[flat];
      };

      std::array<unsigned int, dim> n_block_points;
      for (unsigned int d = 0; d + 1 < dim; ++d)
        n_block_points[d] = n_block[d] + 1;
      n_block_points[dim - 1] = n_height + 1;
      n_points                = 1;
      for (const unsigned int n : n_block_points)
        n_points *= n;
      std::vector<unsigned int> block_vertex;
      for (unsigned int p = 0; p < n_points; ++p)
        {
          std::array<unsigned int, dim> ijk; // in the foundation's grid
          for (unsigned int d = 0, rest = p; d < dim;
               rest /= n_block_points[d], ++d)
            ijk[d] =
              rest % n_block_points[d] + (d + 1 < dim ? n_overhang[d] : 0);
          const unsigned int k = ijk[dim - 1];
          if (k == 0)
            {
              ijk[dim - 1] = n_thickness;
              block_vertex.push_back(std::apply(foundation_index, ijk));
            }
          else
            {
              Tensor<1, dim> frame_point;
              for (unsigned int d = 0; d + 1 < dim; ++d)
                frame_point[d] = lines[d][ijk[d]];
              frame_point[dim - 1] = normal_block_lines[k];
              block_vertex.push_back(add_vertex(frame_point));
            }
        }
      const auto block_index = [&](const auto... indices) {
        const std::array<unsigned int, dim> ijk  = {{indices...}};
        unsigned int                        flat = 0;
        for (unsigned int d = dim; d-- > 0;)
          flat = flat * n_block_points[d] + ijk[d];
        return block_vertex[flat];
      };

      std::array<unsigned int, dim> n_block_cells, n_foundation_cells;
      for (unsigned int d = 0; d < dim; ++d)
        {
          n_block_cells[d]      = n_block_points[d] - 1;
          n_foundation_cells[d] = n_foundation_points[d] - 1;
        }
      add_structured_grid(mesh,
                          n_block_cells,
                          block_index,
                          0,
                          [&](const unsigned int d,
                              const unsigned int side,
                              const auto...) -> unsigned int {
                            return (d + 1 == dim && side == 0) ?
                                     sliding_surface :
                                     block_surface;
                          });
      add_structured_grid(
        mesh,
        n_foundation_cells,
        foundation_index,
        1,
        [&](const unsigned int d,
            const unsigned int side,
            const auto... in_plane) -> unsigned int {
          if (d + 1 < dim)
            return foundation_ends;
          if (side == 0)
            return foundation_base;
          const std::array<unsigned int, dim - 1> cell        = {{in_plane...}};
          bool                                    under_block = true;
          for (unsigned int e = 0; e + 1 < dim; ++e)
            under_block &=
              cell[e] >= n_overhang[e] && cell[e] < n_overhang[e] + n_block[e];
          return under_block ? no_group :
                               static_cast<unsigned int>(foundation_surface);
        });

      if constexpr (dim == 2)
        if (b.element_shape == ElementShape::simplex)
          split_into_triangles(mesh);
      return mesh;
    }



    template struct BlockOnPlane<2>;
    template struct BlockOnPlane<3>;
    template MeshDescription<2>
    make_block_on_plane_mesh(const BlockOnPlane<2> &);
    template MeshDescription<3>
    make_block_on_plane_mesh(const BlockOnPlane<3> &);
  } // namespace geometry
} // namespace fdem
