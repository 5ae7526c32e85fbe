#include "saltus/formats/mass_files.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "saltus/base/text_format.h"
#include "saltus/formats/model_file.h"
#include "saltus/formats/output_folder.h"

namespace saltus {

namespace {

/// Joint wrench (force first) of `segment` at every sample of an evaluation.
const Vector6d& load(const SampleRecord& sample, int segment) {
  return sample.joint_wrench.at(segment);
}

}  // namespace

std::string mass_study_csv(const MassStudyResult& study) {
  std::ostringstream out;
  const char* prefix[] = {"given", "scaled"};
  out << 't';
  for (std::size_t r = 0; r < study.runs.size(); ++r)
    for (const std::string& s : study.load_segments)
      for (const char* q : {"fx", "fy", "fz", "mx", "my", "mz", "force_N", "moment_Nm"})
        out << ',' << prefix[r] << '.' << s << '.' << q;
  out << '\n';
  out.precision(10);
  const std::size_t samples = study.runs.front().result.after.samples.size();
  for (std::size_t k = 0; k < samples; ++k) {
    out << study.runs.front().result.after.samples[k].time;
    for (const MassStudyRun& run : study.runs) {
      const SampleRecord& sample = run.result.after.samples.at(k);
      for (const std::string& s : study.load_segments) {
        const Vector6d& w = load(sample, run.model.segment_index(s));
        for (int i = 0; i < 6; ++i)
          out << ',' << w[i];
        out << ',' << w.head<3>().norm() << ',' << w.tail<3>().norm();
      }
    }
    out << '\n';
  }
  return out.str();
}

std::string mass_study_markdown(const MassStudyResult& study) {
  std::ostringstream out;
  out << "| model | segment | RMS force (N) | peak force (N) | RMS moment (N·m) | peak moment "
         "(N·m) | avg root force after (N) |\n|---|---|---|---|---|---|---|\n";
  std::map<std::string, std::vector<double>> figures;  // segment -> per run RMS force, moment
  for (const MassStudyRun& run : study.runs) {
    for (const std::string& s : study.load_segments) {
      const int index = run.model.segment_index(s);
      double force2 = 0, moment2 = 0, peak_force = 0, peak_moment = 0;
      const auto& samples = run.result.after.samples;
      for (const SampleRecord& sample : samples) {
        const Vector6d& w = load(sample, index);
        force2 += w.head<3>().squaredNorm();
        moment2 += w.tail<3>().squaredNorm();
        peak_force = std::max(peak_force, w.head<3>().norm());
        peak_moment = std::max(peak_moment, w.tail<3>().norm());
      }
      const double n = std::max<std::size_t>(samples.size(), 1);
      const double rms_force = std::sqrt(force2 / n), rms_moment = std::sqrt(moment2 / n);
      figures[s].push_back(rms_force);
      figures[s].push_back(rms_moment);
      out << "| " << run.label << " | " << s << " | " << format_number("%.1f", rms_force) << " | "
          << format_number("%.1f", peak_force) << " | " << format_number("%.2f", rms_moment)
          << " | " << format_number("%.2f", peak_moment) << " | "
          << format_number("%.3g", run.result.after.metrics.avg_root_force) << " |\n";
    }
  }
  if (study.runs.size() == 2) {
    out << "\nScaled / given (RMS):\n\n| segment | force | moment |\n|---|---|---|\n";
    for (const std::string& s : study.load_segments) {
      const std::vector<double>& f = figures[s];
      out << "| " << s << " | " << format_number("%.2f", f[2] / f[0]) << " | "
          << format_number("%.2f", f[3] / f[1]) << " |\n";
    }
  }
  return out.str();
}

nlohmann::json write_mass_outputs(const std::string& out_dir, const MotionFile& file,
                                  const MassStudyResult& study, const MassStudyOptions& options) {
  OutputFolder folder(out_dir);
  nlohmann::json result;
  result["format"] = "saltus-study/1";
  result["study"] = "mass";
  result["status"] = "completed";
  result["motion"] = file.motion.name;
  result["motion_file"] = file.path;
  result["factor"] = options.factor;
  result["scaled_segments"] = options.scaled_segments;
  result["load_segments"] = study.load_segments;
  result["runs"] = nlohmann::json::array();
  for (const MassStudyRun& run : study.runs)
    result["runs"].push_back({{"label", run.label},
                              {"model", run.model.name},
                              {"status", run.result.solve.status},
                              {"iterations", run.result.solve.iterations},
                              {"avg_force_before_N", run.result.before.metrics.avg_root_force},
                              {"avg_force_after_N", run.result.after.metrics.avg_root_force}});
  write_text(folder.file("mass.csv"), mass_study_csv(study));
  write_text(folder.file("mass.md"),
             "# Mass study: " + file.motion.name + "\n\n" + mass_study_markdown(study));
  write_text(folder.file("model.json"), body_model_to_json(study.runs[0].model).dump(2) + "\n");
  write_text(folder.file("model_scaled.json"),
             body_model_to_json(study.runs[1].model).dump(2) + "\n");
  write_text(folder.file("result.json"), result.dump(2) + "\n");
  folder.commit();
  return result;
}

}  // namespace saltus
