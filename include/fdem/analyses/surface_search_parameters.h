// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/analyses/limit_equilibrium.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <vector>

namespace fdem
{
  namespace analyses
  {
    /**
     * The search for the critical circle: subsection "Surface search"
     * (surface_search.h, doc/surface_search.md). Circles from a grid of
     * centres, with radii by tangent elevation or through a point, screened
     * by limit equilibrium, refined around the minimum, the best evaluated
     * with the contact method.
     */
    struct SurfaceSearchParameters
    {
      /** How each centre's radii are chosen. */
      enum class Radii
      {
        /** Circles touching horizontal lines y = y_t: R = y_c - y_t. */
        tangent_elevations,
        /** Circles through one point: R = |centre - point|. */
        through_point
      };

      /** The fewest slices accepted for the screening. */
      static constexpr unsigned int min_n_slices = 10;

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);

      /** Search for the critical circle before the run. */
      bool enabled = false;
      /** Lower-left and upper-right corners of the grid of centres. */
      dealii::Point<2> grid_lower, grid_upper;
      /** Centres along x and along y (1: the corner's coordinate). */
      unsigned int n_x = 10, n_y = 10;
      Radii        radii = Radii::tangent_elevations;
      /** Tangent elevations (Radii = tangent_elevations). */
      std::vector<double> tangent_elevations;
      /** The common point of the circles (Radii = through_point). */
      dealii::Point<2> point;
      /** The screening method. */
      limit_equilibrium::Method method = limit_equilibrium::Method::bishop;
      /** Slices of the screening. */
      unsigned int n_slices = 50;
      /** The refinement stops at this fraction of the grid spacing. */
      double refinement_tolerance = 1e-3;
      /** Contact solves of whole models allowed (0: screening only). */
      unsigned int max_contact_evaluations = 10;
      /** Of these, the best distinct screened circles evaluated first. */
      unsigned int n_contact_candidates = 3;
      /** Circles less deep than this below the ground are skipped. */
      double minimum_depth = 0;
      /** Mesh size of the contact evaluations (0: the model's). */
      double screening_mesh_size = 0;

      /** Interslice surfaces of the polyline candidates' sliding masses. */
      enum class Interslices
      {
        /** One block, 'sliding mass', on 'sliding surface'. */
        none,
        /** Vertical cuts from the interior vertices up to the ground. */
        vertical,
        /** Cuts along the bisectors of the angles at the interior vertices. */
        bisector
      };

      /** The fewest vertices of the non-circular search's polylines. */
      static constexpr unsigned int min_polyline_vertices = 3;

      /** After the circles, optimise a polyline from the best circle. */
      bool non_circular = false;
      /** Vertices of the polyline, its two ends on the ground included. */
      unsigned int n_polyline_vertices = 7;
      /** The screening method of the polylines (not Bishop's). */
      limit_equilibrium::Method polyline_method =
        limit_equilibrium::Method::spencer;
      /** Whether the polylines must be concave upward. */
      bool concave = true;
      /** Of Maximum contact evaluations, those kept for the polylines. */
      unsigned int n_polyline_contact_candidates = 2;
      /**
       * Of Maximum contact evaluations, those kept for the refinement of
       * the best polyline by its contact K (after the candidates).
       */
      unsigned int n_polyline_contact_refinements = 0;
      /** How the polyline candidates' sliding masses are cut into blocks. */
      Interslices polyline_interslices = Interslices::none;
    };
  } // namespace analyses
} // namespace fdem
