// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <deal.II/base/point.h>

#include <vector>

namespace fdem
{
  namespace geometry
  {
    namespace case_input
    {
      /**
       * Whether the segment @p a - @p b runs along the polyline @p line: both
       * ends within 1e-3 of the segment's length of it (a segment that
       * crosses the line has at most one end on it). A face of the mesh or
       * a slice base on a named weak layer.
       */
      bool
      segment_along_polyline(const dealii::Point<2>              &a,
                             const dealii::Point<2>              &b,
                             const std::vector<dealii::Point<2>> &line);
    } // namespace case_input
  }   // namespace geometry
} // namespace fdem
