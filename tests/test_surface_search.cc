// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// The geometry of the non-circular surface search (analyses/surface_search*):
// snap_polyline() against positions worked out by hand, on the paper's
// ground with an inclined layer boundary and a named weak layer.
#include <fdem/analyses/surface_search.h>

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace fdem::analyses;
namespace le = fdem::analyses::limit_equilibrium;
using dealii::Point;

namespace
{
  using Line = std::vector<Point<2>>;

  /**
   * The paper's ground (toe (10, 25), crest (30, 35)) over two layers whose
   * boundary y = 28 + x / 10 meets the face y = 25 + (x - 10) / 2 at
   * (20, 30) and lies below the crest from there on; a weak layer along
   * y = 29 from x = 22 to 45.
   */
  le::Section
  section()
  {
    le::Section s;
    s.ground = {Point<2>(0, 25),
                Point<2>(10, 25),
                Point<2>(30, 35),
                Point<2>(50, 35)};
    le::SoilLayer upper, lower;
    lower.top = {Point<2>(0, 28), Point<2>(50, 33)};
    s.layers  = {upper, lower};
    le::WeakLayer weak;
    weak.line = {Point<2>(22, 29), Point<2>(45, 29)};
    s.weak_layers.push_back(weak);
    return s;
  }

  /**
   * A polyline from the face to the crest: its left end on the face 0.1 in
   * x before the crossing (distance sqrt(0.1^2 + 0.05^2) = 0.1118 from it),
   * vertex 1 0.15 above the weak layer, vertex 2 0.1 below the boundary in
   * y (0.1 / sqrt(1.01) = 0.0995 normal to it), vertex 3 0.3 below it in y
   * (0.2985 normal to it), the right end on the crest, far from any
   * crossing.
   */
  const Line face_to_crest = {Point<2>(19.9, 29.95),
                              Point<2>(25, 29.15),
                              Point<2>(32, 31.1),
                              Point<2>(40, 31.7),
                              Point<2>(45, 35)};

  void
  expect_point(const Point<2> &p, const Point<2> &q, const std::string &what)
  {
    // Round-off of a projection of numbers of order 30: 1e-12 absolute.
    EXPECT_NEAR(p[0], q[0], 1e-12) << what << ", x";
    EXPECT_NEAR(p[1], q[1], 1e-12) << what << ", y";
  }
} // namespace

TEST(SurfaceSearch, SnapPolylineMovesWhatLiesWithinTheDistanceOnly)
{
  const Line snapped = snap_polyline(section(), face_to_crest, 0.2);
  ASSERT_EQ(snapped.size(), face_to_crest.size());
  // Vertex 1, 0.15 above the weak layer: onto it, straight down.
  expect_point(snapped[1], Point<2>(25, 29), "vertex 1 onto the weak layer");
  // Vertex 2, 0.0995 from the boundary: onto its nearest point, the foot of
  // the normal (-0.1, 1) / sqrt(1.01), p + 0.1 / 1.01 (-0.1, 1).
  expect_point(snapped[2],
               Point<2>(32 - 0.01 / 1.01, 31.1 + 0.1 / 1.01),
               "vertex 2 onto the boundary");
  EXPECT_NEAR(snapped[2][1], 28 + snapped[2][0] / 10, 1e-12)
    << "vertex 2 on the boundary";
  // Vertex 3, 0.2985 from the boundary: beyond the distance, not moved.
  EXPECT_EQ(snapped[3], face_to_crest[3]);
  // The left end, 0.1118 from where the boundary meets the ground: moved
  // along the face to (20, 30), then its segment lengthened by 1e-6 of its
  // length (to the snapped vertex 1) beyond it, as every end of the search.
  const Point<2> crossing(20, 30);
  expect_point(snapped[0],
               crossing + 1e-6 * (crossing - Point<2>(25, 29)),
               "left end at the crossing");
  // ... which leaves it just above the face, 3.5e-6 in y (1e-6 of the
  // segment's rise 1, and of its run 5 times the face's slope 1/2).
  EXPECT_NEAR(snapped[0][1] - le::elevation(section().ground, snapped[0][0]),
              1e-6 + 0.5 * 5e-6,
              1e-12);
  // The right end, on the crest and far from any crossing: not moved.
  EXPECT_EQ(snapped[4], face_to_crest[4]);
}

TEST(SurfaceSearch, SnapPolylineLeavesWhatLiesBeyondASmallerDistance)
{
  // A distance of 0.1: only vertex 2 (0.0995 from the boundary) is within
  // it; vertex 1 (0.15) and the left end (0.1118) stay where they are.
  const Line snapped = snap_polyline(section(), face_to_crest, 0.1);
  EXPECT_EQ(snapped[0], face_to_crest[0]);
  EXPECT_EQ(snapped[1], face_to_crest[1]);
  expect_point(snapped[2],
               Point<2>(32 - 0.01 / 1.01, 31.1 + 0.1 / 1.01),
               "vertex 2 onto the boundary");
  EXPECT_EQ(snapped[3], face_to_crest[3]);
  EXPECT_EQ(snapped[4], face_to_crest[4]);
  // A distance of 0: nothing moves.
  EXPECT_EQ(snap_polyline(section(), face_to_crest, 0), face_to_crest);
}

TEST(SurfaceSearch, SnapPolylineTakesTheNearerOfTwoLines)
{
  // Vertex 1 at (30, 29.9): 0.1 above the weak layer and, the boundary at
  // x = 30 being y = 31, 1.1 / sqrt(1.01) = 1.0945 below it; with a
  // distance of 2 both are within reach, the weak layer is nearer.
  Line line = face_to_crest;
  line[1]   = Point<2>(30, 29.9);
  // 0.2 below the boundary in y, 0.199 normal to it; 2.3 from the weak
  // layer.
  line[2]            = Point<2>(35, 31.3);
  const Line snapped = snap_polyline(section(), line, 2);
  expect_point(snapped[1], Point<2>(30, 29), "vertex 1 onto the weak layer");
  expect_point(snapped[2],
               Point<2>(35 - 0.02 / 1.01, 31.3 + 0.2 / 1.01),
               "vertex 2 onto the boundary");
}
