#include "app/cli/study.h"

#include "app/cli/exit_code.h"
#include "sim/measure/accuracy_study.h"
#include "ui/run/accuracy_study_runner.h"

#include <QEventLoop>

#include <algorithm>
#include <cmath>
#include <string_view>
#include <vector>

namespace carom::cli {

int runStudy(const Scene& scene, const StudyOptions& options, QTextStream& out, QTextStream& err) {
  const auto text = [](std::string_view name) {
    return QString::fromUtf8(name.data(), static_cast<qsizetype>(name.size()));
  };
  const std::vector<StudyCase> cases = studyCases(scene.world, kStudyStepFactors);
  ui::AccuracyStudyRunner runner;
  if (options.threads) runner.setMaxThreadCount(*options.threads);
  std::vector<StudyResult> results;
  ui::StudySummary summary;
  QEventLoop loop;
  QObject::connect(&runner, &ui::AccuracyStudyRunner::resultReady,
                   [&results](const StudyResult& result) { results.push_back(result); });
  QObject::connect(&runner, &ui::AccuracyStudyRunner::finished, [&](const ui::StudySummary& done) {
    summary = done;
    loop.quit();
  });
  err << "study: " << cases.size() << " runs of " << options.duration << " s on "
      << runner.maxThreadCount() << " threads...\n";
  err.flush();
  runner.start(scene, cases, options.duration);
  loop.exec();

  // In the order of the cases, not the order they finished in.
  const auto caseIndex = [&cases](const StudyResult& r) {
    for (std::size_t i = 0; i < cases.size(); ++i)
      if (cases[i].method == r.settings.method && cases[i].integrator == r.settings.integrator &&
          cases[i].timeStep == r.settings.timeStep)
        return i;
    return cases.size();
  };
  std::stable_sort(results.begin(), results.end(), [&](const StudyResult& a, const StudyResult& b) {
    return caseIndex(a) < caseIndex(b);
  });
  out << "simulated s  " << options.duration << "\n";
  if (summary.horizon)
    out << "horizon s    " << *summary.horizon
        << "  (the finest setting agrees with exact up to here; position error is taken here)\n";
  else
    out << "horizon s    none  (even the finest setting parts from exact at once)\n";
  out << "method    integrator        dt s        computing s  position error  energy drift"
         "  penetration m  escaped  speeds KS  positions KS\n";
  for (const StudyResult& r : results) {
    out << QString("%1 %2 %3  %4  %5  %6  %7  %8  %9  %10\n")
               .arg(text(methodName(r.settings.method)), -8)
               .arg(text(integratorName(r.settings.integrator)), -17)
               .arg(r.settings.timeStep, -10, 'g', 4)
               .arg(r.computeSeconds, 11, 'f', 3)
               .arg(std::isnan(r.positionError) ? QString("-")
                                                : QString::number(r.positionError, 'e', 3),
                    14)
               .arg(r.energyDrift, 12, 'e', 3)
               .arg(r.maxPenetration, 13, 'e', 3)
               .arg(r.escaped, 7)
               .arg(r.speedDistribution, 9, 'f', 4)
               .arg(r.positionDistribution, 12, 'f', 4);
  }
  out << QString("threads      %1\n").arg(summary.threads)
      << QString("wall s       %1\n").arg(summary.wallSeconds, 0, 'f', 3)
      << QString("reference s  %1\n").arg(summary.referenceSeconds, 0, 'f', 3)
      << QString("runs s       %1\n").arg(summary.computeSeconds, 0, 'f', 3)
      << QString("speed-up     %1\n").arg(summary.speedUp(), 0, 'f', 2);
  return kOk;
}

}  // namespace carom::cli
