#include <tissue_contact/simulation/result_writer.h>

#include <filesystem>
#include <regex>
#include <set>

namespace TissueContact
{
  namespace
  {
    /** @p text as a literal inside a regular expression. */
    std::string
    regex_literal(const std::string &text)
    {
      return std::regex_replace(text,
                                std::regex(R"([.^$|()\[\]{}*+?\\])"),
                                R"(\$&)");
    }
  } // namespace


  void
  clear_old_results(const std::string &directory,
                    const std::string &base_name,
                    const bool         refuse)
  {
    namespace fs = std::filesystem;
    std::error_code error;
    fs::create_directories(directory, error);
    AssertThrow(!error,
                ExcMessage("cannot create the output folder '" + directory +
                           "': " + error.message()));
    const std::string literal = regex_literal(base_name);
    const std::regex  ours(
      literal + R"((-surface)?(-[0-9]+\.vtu|\.pvd)(\.partial)?|)" + literal +
      R"(-(convergence|statistics|time)\.csv|)" + literal +
      R"(-parameters\.prm|)" + literal + R"(-checkpoint\.bin(\.partial)?)");
    std::vector<fs::path> old;
    for (const auto &entry : fs::directory_iterator(directory))
      if (entry.is_regular_file() &&
          std::regex_match(entry.path().filename().string(), ours))
        old.push_back(entry.path());
    if (old.empty())
      return;
    AssertThrow(!refuse,
                ExcMessage("the output folder '" + directory +
                           "' holds results of an earlier run with the base "
                           "name '" +
                           base_name + "' (" + old.front().filename().string() +
                           " and " + std::to_string(old.size() - 1) +
                           " more): move them, choose another Output/Base "
                           "name or Directory, or set Output/Old results = "
                           "remove"));
    for (const auto &f : old)
      {
        fs::remove(f, error);
        AssertThrow(!error,
                    ExcMessage("cannot remove the earlier run's file '" +
                               f.string() + "': " + error.message()));
      }
  }


  namespace
  {
    /** Prepares the output folder: a new run clears an earlier run's files
     * (or refuses); a restarted one cuts the CSV files to their length at
     * the checkpoint and removes the VTU files written after it. Returns
     * the statistics file's path. */
    std::string
    prepared_statistics_path(const Problem &problem, const Checkpoint *restart)
    {
      namespace fs   = std::filesystem;
      const auto &o  = problem.get_scene().parameters.output;
      const auto  in = [&](const std::string &name) {
        return o.directory + "/" + name;
      };
      if (restart == nullptr)
        clear_old_results(o.directory, o.base_name, o.old_results == "refuse");
      else
        {
          for (const auto &[name, size] : restart->file_sizes)
            {
              AssertThrow(fs::exists(in(name)) &&
                            fs::file_size(in(name)) >= size,
                          ExcMessage("the file '" + in(name) +
                                     "' the checkpoint continues is missing "
                                     "or shorter than when it was written"));
              fs::resize_file(in(name), size);
            }
          std::set<std::string> kept;
          for (const auto &r : restart->vtu_records)
            kept.insert(r.second);
          for (const auto &r : restart->surface_records)
            kept.insert(r.second);
          const std::regex vtu(regex_literal(o.base_name) +
                               R"((-surface)?-[0-9]+\.vtu(\.partial)?)");
          for (const auto &entry : fs::directory_iterator(o.directory))
            {
              const std::string name = entry.path().filename().string();
              if (std::regex_match(name, vtu) && kept.count(name) == 0)
                fs::remove(entry.path());
            }
        }
      const std::string &effective =
        problem.get_scene().parameters.effective_parameters;
      if (!effective.empty())
        Output::write_file_atomically(in(o.base_name + "-parameters.prm"),
                                      effective);
      return in(o.base_name + "-statistics.csv");
    }
  } // namespace


  ResultWriter::ResultWriter(const Problem &problem, const Checkpoint *restart)
    : problem(problem)
    , statistics(prepared_statistics_path(problem, restart), restart != nullptr)
  {
    const auto &o = problem.get_scene().parameters.output;
    if (!o.write_vtu)
      return;
    Output::VtuSeriesWriter::Options options;
    options.double_precision = o.double_precision;
    options.length_unit      = o.length_unit;
    if (!o.force_unit.empty() && !o.length_unit.empty())
      options.stress_unit = o.force_unit + "/" + o.length_unit + "^2";
    vtu = std::make_unique<Output::VtuSeriesWriter>(problem.discretization(),
                                                    o.directory,
                                                    o.base_name,
                                                    options);
    if (const auto *contact = problem.contact_assembler())
      vtu->set_surface(contact->contact_surface().triangles,
                       contact->contact_surface().triangle_body);
    if (restart != nullptr)
      vtu->continue_series(restart->vtu_records, restart->surface_records);
  }


  bool
  ResultWriter::checkpoint_due(const unsigned int step) const
  {
    const unsigned int n =
      problem.get_scene().parameters.output.checkpoint_every;
    return n > 0 && step % n == 0;
  }


  void
  ResultWriter::write_checkpoint(Checkpoint                      c,
                                 const std::vector<std::string> &csv_files)
  {
    const auto &p = problem.get_scene().parameters;
    c.parameters  = p.effective_parameters;
    for (const std::string &file : csv_files)
      c.file_sizes[std::filesystem::path(file).filename().string()] =
        std::filesystem::file_size(file);
    const std::string path =
      checkpoint_file(p.output.directory, p.output.base_name);
    if (!vtu)
      {
        c.write(path);
        return;
      }
    // after the VTU files it lists, on their writing thread: a checkpoint
    // never names a file that is not complete
    vtu->then([c = std::move(c),
               path](const Output::VtuSeriesWriter::Records &v,
                     const Output::VtuSeriesWriter::Records &s) mutable {
      c.vtu_records     = v;
      c.surface_records = s;
      c.write(path);
    });
  }


  bool
  ResultWriter::due(const unsigned int step) const
  {
    return vtu &&
           step % problem.get_scene().parameters.output.every_n_steps == 0;
  }


  std::string
  ResultWriter::pvd_file() const
  {
    return vtu ? vtu->pvd_file() : std::string();
  }


  StepResults
  ResultWriter::record(const unsigned int    step,
                       const double          time,
                       const Vector<double> &u,
                       const double          load_factor,
                       const bool            write_vtu,
                       const std::vector<std::pair<std::string, double>> &extra)
  {
    StepResults results(problem, u, load_factor);
    std::vector<std::pair<std::string, double>> row = {
      {"step", step},
      {problem.get_scene().parameters.time_integration.dynamic ? "time" :
                                                                 "load_factor",
       time}};
    row.insert(row.end(), extra.begin(), extra.end());
    const auto columns = results.columns();
    row.insert(row.end(), columns.begin(), columns.end());
    statistics.write_row(row);

    if (write_vtu && vtu)
      {
        std::vector<Output::VertexField> fields;
        const Vector<double>             u_fe = problem.displacement(u);
        // the vertex pressures of bodies with Volumetric term = nodal
        // average (doc/theory/08-nodal-pressure.md)
        std::vector<double> p =
          problem.elastic_assembler().vertex_pressure(u_fe);
        if (!p.empty())
          fields.push_back({"hydrostatic_stress", 1, std::move(p), "stress"});
        if (const auto *depth = problem.depth_field())
          fields.push_back({"material_depth", 1, *depth, "length"});
        if (problem.contact_assembler())
          {
            const auto         &c = results.contact;
            Output::VertexField traction{"contact_traction", 3, {}, "stress"};
            traction.values.reserve(3 * c.traction.size());
            for (const auto &t : c.traction)
              for (unsigned int d = 0; d < 3; ++d)
                traction.values.push_back(t[d]);
            fields.push_back(traction);
            fields.push_back({"contact_pressure", 1, c.pressure, "stress"});
            fields.push_back({"penetration", 1, c.penetration, "length"});
          }
        vtu->write(problem.elastic_assembler(), u_fe, time, fields);
      }
    return results;
  }
} // namespace TissueContact
