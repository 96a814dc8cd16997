// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <deal.II/base/point.h>

#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace fdem
{
  namespace analyses
  {
    /**
     * Limit equilibrium by the method of slices on a 2D section: the C++ form
     * of tools/limit_equilibrium.py (doc/limit_equilibrium.md), the same
     * slicing and the same equations, so that both give the same factors to
     * round-off. Lengths in the model's unit, x to the right, y up, gravity
     * along -y.
     */
    namespace limit_equilibrium
    {
      using dealii::Point;

      /** One soil layer: its top line, unit weights and strength. */
      struct SoilLayer
      {
        /** Top line from left to right; empty: the ground surface. */
        std::vector<Point<2>> top;
        /** Unit weight above the piezometric line (force/length^3). */
        double unit_weight = 20;
        /** Unit weight below the piezometric line (force/length^3). */
        double saturated_unit_weight = 20;
        /** Cohesion c (force/length^2). */
        double cohesion = 0;
        /** Friction angle phi (degrees). */
        double friction_angle = 30;
        /**
         * The layer's own piezometric line (a perched water table), from
         * left to right: its wet part and a base in it use this line.
         * Empty: the section's.
         */
        std::vector<Point<2>> piezometric;
      };

      /**
       * An active anchor (analyses/anchors.h): the force T pulls the mass at
       * its head towards the bond point. On the slices it acts at the point
       * where it crosses the sliding surface, on the base of that slice, split
       * into the part normal to the base and the part along it.
       */
      struct Anchor
      {
        Point<2> head, bond;
        double   force = 0;
        /**
         * A passive bar (analyses/bars.h) at its capacity instead: force is
         * its tensile capacity, limited where it crosses by @p pullout
         * (per unit length, 0: none) times its length on either side, with
         * a pile's @p shear_capacity across it (resisting the slide), and
         * all of it divided by K if @p reduced (the anchors' convention
         * does not apply to it).
         */
        bool   passive_bar = false, reduced = false;
        double pullout = 0, shear_capacity = 0;
      };

      /**
       * A named weak layer (Materials/<name>/Weak layer): a slice base along
       * its line (both ends within 1e-3 of the base's length) takes its
       * strength instead of the layer's.
       */
      struct WeakLayer
      {
        std::vector<Point<2>> line;
        /** Cohesion c (force/length^2). */
        double cohesion = 0;
        /** Friction angle phi (degrees). */
        double friction_angle = 0;
      };

      /**
       * The section: ground, layers top down (each below its top line down to
       * the next layer's top), piezometric line and the unit weight of water.
       * Below the piezometric line (the layer's own, if it has one) a layer
       * weighs its saturated unit weight and, with @p pore_pressure, a base
       * in it carries gamma_w (y_w - y).
       */
      struct Section
      {
        std::vector<Point<2>>  ground;
        std::vector<SoilLayer> layers;
        /** Empty: no water. */
        std::vector<Point<2>> piezometric;
        double                water_unit_weight = 9.81;
        /** Whether the base carries the piezometric pore pressure. */
        bool pore_pressure = true;
        /**
         * Pseudo-static seismic coefficients: a horizontal force kh W' at
         * each slice's centroid in the direction the mass slides (towards
         * the free face), and kv W' upwards, W' the slice's weight with the
         * unit weight above and below the piezometric line, or with the
         * saturated one below it if @p seismic_on_pore_water (as the FE
         * model's Loads/Seismic force on pore water).
         */
        double kh = 0, kv = 0;
        bool   seismic_on_pore_water = false;
        /** 0: kh towards the free face; +1 or -1: a positive kh along +x or -x.
         */
        int kh_direction = 0;
        /** Active anchors across the sliding surface. */
        std::vector<Anchor> anchors;
        /** Whether the anchors' part along the base is divided by K (method B).
         */
        bool anchors_reduced_by_K = false;
        /** Named weak layers that slice bases may run along. */
        std::vector<WeakLayer> weak_layers;
      };

      /** The sliding surface: a circle or a polyline, with a tension crack. */
      struct Surface
      {
        bool     circular = false;
        Point<2> centre;
        double   radius = 0;
        /** From left to right (where circular is false). */
        std::vector<Point<2>> polyline;
        /** Depth of the vertical crack at the upper end (0: none). */
        double crack_depth = 0;
        /** Water in the crack above its bottom. */
        double crack_water_depth = 0;
      };

      /** The methods. */
      enum class Method
      {
        /** Fellenius: interslice forces neglected. */
        ordinary,
        /** Bishop's simplified method (circles): no interslice shear. */
        bishop,
        /** Janbu's simplified method, force equilibrium, no interslice shear.
         */
        janbu,
        /** Janbu's simplified method times the correction factor f0. */
        janbu_corrected,
        /** Spencer: X = lambda E, force and moment equilibrium. */
        spencer,
        /** Morgenstern-Price with f(x) = 1 (Spencer's assumption). */
        morgenstern_price_constant,
        /** Morgenstern-Price with f(x) = sin(pi (x - x_toe) / (x_crest -
           x_toe)). */
        morgenstern_price_half_sine
      };

      /** The key of @p method in summary.json ("spencer", ...). */
      std::string
      method_key(const Method method);

      /** One method's answer on one surface. */
      struct MethodResult
      {
        Method method = Method::spencer;
        /** Factor of safety. */
        double K = std::numeric_limits<double>::quiet_NaN();
        /**
         * Spencer and Morgenstern-Price: the scale lambda of the interslice
         * function (X = lambda f(x) E); NaN if moment equilibrium does not fix
         * it (a plane without cohesion) or not applicable.
         */
        double lambda = std::numeric_limits<double>::quiet_NaN();
        /** Janbu corrected: the correction factor f0. */
        double f0 = std::numeric_limits<double>::quiet_NaN();
        /** Number of slices (at least the number asked for). */
        unsigned int n_slices = 0;
      };

      /**
       * One slice: weight W, x of its line of action, base angle alpha
       * (positive where the base rises to the right, in the frame where the
       * mass moves left), base length l, base midpoint, pore force U on the
       * base, its strength; sin and cos of alpha, computed once (the root
       * searches evaluate every slice thousands of times).
       */
      struct Slice
      {
        double W, xg, alpha, l, xm, ym, U, c, tan_phi, sin_alpha, cos_alpha;
        /**
         * The seismic forces: the horizontal kh W' (pushing the way the
         * mass moves, i.e. to the left here) and the vertical kv W'
         * (upwards), at the height yg of the slice's centroid; W' is W, or
         * W with the unit weight below the piezometric line
         * (Section::seismic_on_pore_water false).
         */
        double Q = 0, V = 0, yg = 0;
        /**
         * The anchors crossing the base of this slice: the sums of their
         * parts normal to the base (Nx, Ny) and along it (Sx, Sy), x to the
         * right and y up, and each part's moment about the origin (x F_y -
         * y F_x at the crossing).
         */
        double Nx = 0, Ny = 0, Sx = 0, Sy = 0, Mn = 0, Ms = 0;
        /**
         * The passive bars crossing it at their capacities: the forces K
         * does not reduce (Fx, Fy, their moment Mf about the origin) and
         * those it divides (Rx, Ry, Mr).
         */
        double Fx = 0, Fy = 0, Mf = 0, Rx = 0, Ry = 0, Mr = 0;

        /** The anchors' and bars' force on the slice at K: the anchors' part
         * along the base divided by K if @p reduced. */
        double
        anchor_x(const double K, const bool reduced) const
        {
          return Nx + (reduced ? Sx / K : Sx) + Fx + Rx / K;
        }
        double
        anchor_y(const double K, const bool reduced) const
        {
          return Ny + (reduced ? Sy / K : Sy) + Fy + Ry / K;
        }
        /** Their moment about the point @p c at K. */
        double
        anchor_moment(const double    K,
                      const bool      reduced,
                      const Point<2> &c) const
        {
          const double scale = reduced ? 1 / K : 1.;
          return Mn + scale * Ms + Mf + Mr / K -
                 (c[0] * anchor_y(K, reduced) - c[1] * anchor_x(K, reduced));
        }
      };

      /**
       * The sliding mass cut into slices, in a frame where it moves to the
       * left (mirrored if it moves to the right), as SlicedMass of
       * tools/limit_equilibrium.py: slice boundaries at every vertex and
       * crossing of the lines, and slices of about equal width between.
       */
      struct SlicedMass
      {
        SlicedMass(const Section     &section,
                   const Surface     &surface,
                   const unsigned int n_slices);

        bool                   mirrored = false;
        std::vector<Point<2>>  ground, surface, piezometric;
        std::vector<SoilLayer> layers;
        std::vector<WeakLayer> weak_layers;
        double                 water_unit_weight;
        bool                   pore_pressure;
        /** The section's seismic coefficients (Section::kh, kv). */
        double kh = 0, kv = 0;
        bool   seismic_on_pore_water = false;
        /** Section::anchors_reduced_by_K. */
        bool anchors_reduced = false;
        /** Whether an anchor crosses a slice's base: without one the root
         * searches march without the anchors' terms. */
        bool has_anchors = false;
        /** The crack's water force (pushing left) and its point of action. */
        double              crack_force = 0;
        Point<2>            crack_point;
        std::vector<double> x;
        std::vector<Slice>  slices;
        /** Circle centre in this frame (for circles). */
        Point<2> centre;
        double   radius   = 0;
        bool     circular = false;
      };

      /**
       * The arc of a circle below the ground as a polyline of @p n_points
       * equally spaced in x, its end points on the ground. Throws if the
       * circle does not cut the ground.
       */
      std::vector<Point<2>>
      circle_surface(const std::vector<Point<2>> &ground,
                     const Point<2>              &centre,
                     const double                 radius,
                     const unsigned int           n_points);

      /**
       * The part of @p polyline below the ground, its end points on the
       * ground. Throws if it does not pass below the ground.
       */
      std::vector<Point<2>>
      polyline_in_ground(const std::vector<Point<2>> &ground,
                         const std::vector<Point<2>> &polyline);

      /**
       * @p method on @p mass; @p tolerance is the absolute tolerance of the
       * roots in K and lambda. Throws (one sentence) when the method has no
       * answer (e.g. Bishop on a polyline, no root in [0.05, 50]).
       */
      MethodResult
      solve(const SlicedMass &mass,
            const Method      method,
            const double      tolerance);

      /** The elevation of a polyline at x, constant beyond its ends
       * (np.interp): geometry::case_input::polyline_elevation(). */
      double
      elevation(const std::vector<Point<2>> &line, const double x);

      /**
       * A root of @p f in [a, b] (f(a) f(b) <= 0) by Brent's method, the
       * algorithm of scipy.optimize.brentq with its stopping rule
       * |step| < (xtol + rtol |x|) / 2, so that the C++ and the Python
       * yardstick stop at the same place.
       */
      double
      find_root(const std::function<double(double)> &f,
                double                               a,
                double                               b,
                const double                         xtol,
                const double rtol = 8.881784197001252e-16);
    } // namespace limit_equilibrium
  }   // namespace analyses
} // namespace fdem
