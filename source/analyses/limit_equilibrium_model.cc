// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// The model's own section for limit equilibrium, every method on it, and
// how the answers are reported (summary.json and the screen).
#include <fdem/analyses/limit_equilibrium_model.h>
#include <fdem/postprocess/json_number.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace fdem
{
  namespace analyses
  {
    using namespace dealii;
    namespace le = limit_equilibrium;

    namespace
    {
      std::vector<Point<2>>
      points(const std::vector<std::array<double, 2>> &line)
      {
        std::vector<Point<2>> out;
        for (const auto &p : line)
          out.emplace_back(p[0], p[1]);
        return out;
      }

      /** Why the model's section cannot be built, or "" if it can. */
      std::string
      unsupported(const parameters::Parameters &p)
      {
        const auto &g = p.geometry;
        if (g.source != parameters::GeometryParameters::Source::slope ||
            p.dimension != 2)
          return "it needs the slope generator's section (Geometry/Source = "
                 "slope, 2D): ground, layers and sliding surface as lines";
        if (g.scale_factor != 1 || g.rotation_angle != 0 ||
            std::any_of(g.translation.begin(),
                        g.translation.end(),
                        [](const double t) { return t != 0; }))
          return "the model is transformed (Geometry's scale, rotation or "
                 "translation) and the section is not";
        const auto &d = p.loads.gravity_direction;
        if (d.size() != 2 || d[0] != 0 || !(d[1] < 0))
          return "gravity is not along -y (Loads/Gravity direction)";
        return "";
      }
    } // namespace

    void
    check_surface_in_model(const le::Section &section,
                           const le::Surface &surface,
                           const double       base_elevation)
    {
      const auto line =
        surface.circular ?
          le::circle_surface(section.ground,
                             surface.centre,
                             surface.radius,
                             2001) :
          le::polyline_in_ground(section.ground, surface.polyline);
      double lowest = line.front()[1];
      for (const Point<2> &q : line)
        lowest = std::min(lowest, q[1]);
      const double x_left      = section.ground.front()[0],
                   x_right     = section.ground.back()[0];
      const double       slack = 1e-9 * (x_right - x_left);
      std::ostringstream where;
      where << "from x = " << line.front()[0] << " to " << line.back()[0]
            << ", down to y = " << lowest << "; the model spans x = " << x_left
            << " to " << x_right << " above y = " << base_elevation;
      AssertThrow(line.front()[0] > x_left - slack &&
                    line.back()[0] < x_right + slack && lowest > base_elevation,
                  ExcMessage(
                    "Geometry/Slope: the sliding surface leaves the model "
                    "for limit equilibrium (" +
                    where.str() + ")."));
    }

    bool
    model_section(const parameters::Parameters &p,
                  le::Section                  &section,
                  le::Surface                  &surface,
                  std::string                  &why_not,
                  std::vector<std::string>     &notes,
                  const bool                    check_surface)
    {
      why_not = unsupported(p);
      if (!why_not.empty())
        return false;
      const auto  &slope = p.geometry.slope;
      const double g     = p.loads.gravitational_acceleration;

      // The sliding surface's interfaces: one strength and one pore pressure.
      std::vector<std::string> surfaces;
      for (const std::string &name : p.interface_names)
        if (p.interfaces.at(name).sliding_surface)
          surfaces.push_back(name);
      if (surfaces.empty())
        {
          why_not = "no interface is a sliding surface";
          return false;
        }
      const auto &first = p.interfaces.at(surfaces.front());
      for (const std::string &name : surfaces)
        {
          const auto &i = p.interfaces.at(name);
          if (i.strength_from_material != first.strength_from_material ||
              (!i.strength_from_material &&
               (i.cohesion != first.cohesion ||
                i.friction_angle != first.friction_angle ||
                i.frictionless != first.frictionless)))
            {
              why_not = "the sliding surface's interfaces have different "
                        "strengths ('" +
                        surfaces.front() + "', '" + name + "')";
              return false;
            }
          if (Utilities::trim(i.pore_pressure) !=
              Utilities::trim(first.pore_pressure))
            {
              why_not =
                "the sliding surface's interfaces have different pore pressures";
              return false;
            }
        }
      const std::string pore = Utilities::trim(first.pore_pressure);
      if (pore != "0" && pore != "piezometric")
        {
          why_not = "the pore pressure of '" + surfaces.front() +
                    "' is a function, not 'piezometric' or 0";
          return false;
        }
      section.pore_pressure     = pore == "piezometric";
      section.water_unit_weight = p.water.unit_weight;
      // The FE model's pseudo-static seismic load (Loads/...), the same on
      // the slices.
      section.kh                    = p.loads.horizontal_seismic_coefficient;
      section.kv                    = p.loads.vertical_seismic_coefficient;
      section.seismic_on_pore_water = p.loads.seismic_on_pore_water;
      if (!p.loads.seismic_direction.empty())
        section.kh_direction = p.loads.seismic_direction[0] > 0 ? 1 : -1;
      // The anchors, at the base of the slice where each crosses the surface.
      section.anchors.clear();
      section.anchors_reduced_by_K = p.anchors.reduced_by_K;
      for (unsigned int k = 0; k < p.anchors.n_anchors(); ++k)
        if (p.anchors.heads[k].size() == 2 &&
            p.anchors.bond_points[k].size() == 2)
          section.anchors.push_back(
            {Point<2>(p.anchors.heads[k][0], p.anchors.heads[k][1]),
             Point<2>(p.anchors.bond_points[k][0], p.anchors.bond_points[k][1]),
             p.anchors.forces[k]});
      for (unsigned int k = 0; k < p.anchors.n_bars(); ++k)
        if (p.anchors.bar_heads[k].size() == 2 &&
            p.anchors.bar_ends[k].size() == 2)
          {
            le::Anchor bar;
            bar.head =
              Point<2>(p.anchors.bar_heads[k][0], p.anchors.bar_heads[k][1]);
            bar.bond =
              Point<2>(p.anchors.bar_ends[k][0], p.anchors.bar_ends[k][1]);
            bar.force          = p.anchors.bar_tensile_capacities[k];
            bar.passive_bar    = true;
            bar.reduced        = p.anchors.bar_capacity_reduced_by_K;
            bar.pullout        = p.anchors.bar_pullout_resistances[k];
            bar.shear_capacity = p.anchors.bar_shear_capacities[k];
            section.anchors.push_back(bar);
          }
      if (p.anchors.n_bars() > 0)
        notes.push_back(
          "the passive bars act at their capacities at the base of the slice where each "
          "crosses the sliding surface (in the FE model where they have yielded)");
      if (p.anchors.n_anchors() > 0)
        notes.push_back(
          "the anchors act on the base of the slice where each crosses the sliding surface "
          "(in the FE model at their heads: the same line of action)");
      section.piezometric = points(p.water.piezometric_line);
      section.ground      = slope.ground_surface;

      const auto strength = [&](le::SoilLayer                        &layer,
                                const parameters::MaterialParameters &m) {
        layer.cohesion =
          first.strength_from_material ? m.cohesion : first.cohesion;
        layer.friction_angle = first.strength_from_material ? m.friction_angle :
                               first.frictionless           ? 0. :
                                                    first.friction_angle;
      };
      section.weak_layers.clear();
      if (first.strength_from_material)
        for (const std::string &name : p.material_names)
          if (!p.materials.at(name).weak_layer.empty())
            {
              const auto &m = p.materials.at(name);
              section.weak_layers.push_back(
                {m.weak_layer, m.cohesion, m.friction_angle});
            }
      section.layers.clear();
      // A layer without a material is the model's error, reported when the
      // blocks are set up; no section here.
      for (const std::string &name : slope.layers)
        if (p.materials.count(name) == 0)
          {
            why_not = "the layer material '" + name + "' is not declared";
            return false;
          }
      if (!slope.layers.empty())
        for (unsigned int k = 0; k < slope.layers.size(); ++k)
          {
            const auto   &m = p.materials.at(slope.layers[k]);
            le::SoilLayer layer;
            if (k > 0)
              layer.top = slope.layer_boundaries[k - 1];
            layer.unit_weight           = m.weight(g);
            layer.saturated_unit_weight = m.saturated_weight(g);
            layer.piezometric           = points(m.piezometric_line);
            strength(layer, m);
            section.layers.push_back(layer);
          }
      else
        {
          // The sliding mass's blocks ("sliding mass", "sliding mass i"):
          // one material.
          const parameters::MaterialParameters *mass = nullptr;
          for (const std::string &name : p.block_names)
            if (name.rfind("sliding mass", 0) == 0 && p.materials.count(name))
              {
                const auto &m = p.materials.at(name);
                if (mass != nullptr &&
                    (m.weight(g) != mass->weight(g) ||
                     m.saturated_weight(g) != mass->saturated_weight(g)))
                  {
                    why_not =
                      "the blocks of the sliding mass have different unit weights";
                    return false;
                  }
                mass = &m;
              }
          if (mass == nullptr)
            {
              why_not = "no block 'sliding mass' gives the mass's unit weight";
              return false;
            }
          le::SoilLayer layer;
          layer.unit_weight           = mass->weight(g);
          layer.saturated_unit_weight = mass->saturated_weight(g);
          layer.piezometric           = points(mass->piezometric_line);
          strength(layer, *mass);
          section.layers.push_back(layer);
        }

      surface.circular =
        slope.sliding_surface == geometry::Slope::SlidingSurface::circular;
      surface.centre   = slope.circle_centre;
      surface.radius   = slope.circle_radius;
      surface.polyline = slope.sliding_surface_polyline;
      for (unsigned int i = 1; i < surface.polyline.size(); ++i)
        if (surface.polyline[i][0] == surface.polyline[i - 1][0])
          {
            why_not = "the polyline sliding surface has a vertical segment, "
                      "which no vertical slice can hold";
            return false;
          }
      surface.crack_depth       = slope.tension_crack_depth;
      surface.crack_water_depth = slope.tension_crack_water_depth;

      // The surface must lie inside the model: its ends within the ground's
      // x range, and above the base.
      if (check_surface)
        check_surface_in_model(section, surface, slope.base_elevation);

      // Loads of the FE model that the section does not carry.
      bool crack_pressure = false;
      for (const std::string &name : p.boundary_names)
        {
          const auto &b      = p.boundaries.at(name);
          const bool  loaded = Utilities::trim(b.pressure) != "0" ||
                              Utilities::trim(b.traction) != "0";
          if (loaded && name == "tension crack")
            crack_pressure = true;
          else if (loaded)
            notes.push_back("the load on boundary '" + name +
                            "' is not represented in limit equilibrium");
        }
      if (crack_pressure)
        notes.push_back("the tension crack's water is the hydrostatic force of "
                        "Tension crack water depth, not the boundary pressure "
                        "of 'tension crack'");
      else if (surface.crack_water_depth > 0)
        notes.push_back(
          "limit equilibrium includes the water in the tension "
          "crack, which no boundary pressure puts on the FE model");
      return true;
    }

    LimitEquilibriumResults
    evaluate_limit_equilibrium(const le::Section                &section,
                               const le::Surface                &surface,
                               const LimitEquilibriumParameters &settings)
    {
      LimitEquilibriumResults results;
      // Geometry errors (a surface outside the ground) are the user's and
      // propagate; a method without an answer is reported as such.
      const le::SlicedMass mass(section, surface, settings.n_slices);
      const le::SlicedMass finer(section, surface, 2 * settings.n_slices);
      results.computed = true;
      for (const le::Method method : settings.methods)
        {
          LimitEquilibriumResults::Entry entry;
          entry.method = method;
          try
            {
              entry.result  = le::solve(mass, method, settings.tolerance);
              entry.doubled = le::solve(finer, method, settings.tolerance);
            }
          catch (const ExceptionBase &error)
            {
              entry.not_computed      = error.get_exc_name();
              const std::string text  = error.what();
              const auto        start = text.find("Limit equilibrium: ");
              entry.not_computed      = start == std::string::npos ?
                                          "no answer" :
                                          text.substr(start + 19);
              entry.not_computed =
                entry.not_computed.substr(0, entry.not_computed.find('\n'));
            }
          results.methods.push_back(entry);
        }
      return results;
    }

    LimitEquilibriumResults
    model_limit_equilibrium(const parameters::Parameters &parameters)
    {
      LimitEquilibriumResults results;
      if (!parameters.limit_equilibrium.enabled)
        {
          results.not_computed = "Limit equilibrium/Enabled is false";
          return results;
        }
      le::Section              section;
      le::Surface              surface;
      std::string              why_not;
      std::vector<std::string> notes;
      if (!model_section(parameters, section, surface, why_not, notes))
        {
          results.not_computed =
            "limit equilibrium: not available for this geometry because " +
            why_not + ".";
          return results;
        }
      try
        {
          results = evaluate_limit_equilibrium(section,
                                               surface,
                                               parameters.limit_equilibrium);
        }
      catch (const ExceptionBase &error)
        {
          // A section the slicing cannot take (e.g. a crack deeper than the
          // surface at its upper end) leaves the FE run alone.
          const std::string text  = error.what();
          const auto        start = text.find("Limit equilibrium: ");
          results.not_computed =
            "limit equilibrium: not available for this geometry because " +
            (start == std::string::npos ?
               std::string("the section cannot be sliced") :
               text.substr(start + 19, text.find('\n', start) - start - 19));
        }
      results.notes = notes;
      return results;
    }

    namespace
    {
      std::string
      label(const le::Method method)
      {
        switch (method)
          {
            case le::Method::ordinary:
              return "ordinary (Fellenius)";
            case le::Method::bishop:
              return "Bishop simplified";
            case le::Method::janbu:
              return "Janbu simplified";
            case le::Method::janbu_corrected:
              return "Janbu corrected";
            case le::Method::spencer:
              return "Spencer";
            case le::Method::morgenstern_price_constant:
              return "Morgenstern-Price, f = 1";
            case le::Method::morgenstern_price_half_sine:
              return "Morgenstern-Price, half-sine";
          }
        return "";
      }
    } // namespace

    nlohmann::json
    to_json(const LimitEquilibriumResults &results)
    {
      nlohmann::json out     = {{"computed", results.computed},
                                {"not_computed", results.not_computed},
                                {"notes", results.notes}};
      nlohmann::json methods = nlohmann::json::object();
      for (const auto &entry : results.methods)
        {
          nlohmann::json m;
          if (!entry.not_computed.empty())
            m = {{"K", nullptr}, {"not_computed", entry.not_computed}};
          else
            {
              const double K = entry.result.K, K2 = entry.doubled.K;
              m = {{"K", K},
                   {"n_slices", entry.result.n_slices},
                   {"K_doubled_slices", K2},
                   {"n_slices_doubled", entry.doubled.n_slices},
                   {"relative_change_doubled_slices", (K2 - K) / K}};
              if (entry.method == le::Method::spencer ||
                  entry.method == le::Method::morgenstern_price_constant ||
                  entry.method == le::Method::morgenstern_price_half_sine)
                {
                  m["lambda"] =
                    postprocess::number_or_null(entry.result.lambda);
                  if (entry.method != le::Method::morgenstern_price_half_sine)
                    m["theta_degrees"] = postprocess::number_or_null(
                      std::atan(entry.result.lambda) * 180 / M_PI);
                }
              if (entry.method == le::Method::janbu_corrected)
                m["f0"] = entry.result.f0;
            }
          methods[le::method_key(entry.method)] = m;
        }
      out["methods"] = methods;
      return out;
    }

    void
    print_limit_equilibrium(const LimitEquilibriumResults &results,
                            std::ostream                  &out)
    {
      std::ostringstream text; // not to leave the log's format changed
      if (!results.computed)
        {
          if (!results.not_computed.empty())
            text << results.not_computed << "\n";
          out << text.str() << std::flush;
          return;
        }
      text << "Limit equilibrium on the same surface:\n";
      for (const auto &entry : results.methods)
        {
          text << "  " << std::left << std::setw(30)
               << label(entry.method) + ":";
          if (!entry.not_computed.empty())
            {
              text << "not computed: " << entry.not_computed << "\n";
              continue;
            }
          const double K = entry.result.K;
          text << "K = " << std::fixed << std::setprecision(4) << K;
          if (std::isfinite(entry.result.lambda))
            text << ", lambda = " << std::setprecision(4)
                 << entry.result.lambda;
          text << std::defaultfloat << " (" << entry.result.n_slices
               << " slices; twice as many: " << std::showpos
               << std::setprecision(1) << std::scientific
               << (entry.doubled.K - K) / K << std::noshowpos
               << std::defaultfloat << " relative)\n";
        }
      for (const std::string &note : results.notes)
        text << "  note: " << note << "\n";
      out << text.str() << std::flush;
    }
  } // namespace analyses
} // namespace fdem
