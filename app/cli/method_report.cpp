#include "app/cli/method_report.h"

#include <QJsonArray>

#include <cmath>

namespace carom::cli {
namespace {

QString text(std::string_view name) {
  return QString::fromUtf8(name.data(), static_cast<qsizetype>(name.size()));
}

}  // namespace

QString settingsText(const StudyCase& settings) {
  if (settings.method == Method::Exact) return text(methodName(settings.method));
  return QString("%1 (%2, dt %3 s)")
      .arg(text(methodName(settings.method)), text(integratorName(settings.integrator)))
      .arg(settings.timeStep, 0, 'g', 4);
}

void printChoice(QTextStream& out, const MethodChoice& choice, const AccuracyTolerance& tolerance) {
  out << "auto: tolerance: energy error " << tolerance.energyPerSecond
      << " per simulated second, penetration " << tolerance.penetrationFraction
      << " of the radius\n";
  out << QString("auto: pilot of %1 simulated s, %2 s of computing\n")
             .arg(choice.pilotSimulated, 0, 'g', 4)
             .arg(choice.pilotSeconds, 0, 'g', 3);
  out << "auto: candidate                               cost s/s  energy err/s  penetration"
         "  escaped  verdict\n";
  for (const PilotMeasure& m : choice.candidates)
    out << QString("auto: %1 %2  %3  %4  %5  %6\n")
               .arg(settingsText(m.settings), -40)
               .arg(m.costPerSecond, 9, 'e', 2)
               .arg(m.energyErrorPerSecond, 12, 'e', 2)
               .arg(m.penetrationFraction, 11, 'e', 2)
               .arg(m.escaped, 7)
               .arg(QString::fromStdString(m.verdict));
  if (choice.candidates.empty()) return;
  if (choice.chosen)
    out << "auto: chose " << settingsText(choice.pick().settings) << ": "
        << QString::fromStdString(choice.reason) << "\n";
  else
    out << "auto: " << QString::fromStdString(choice.reason) << ": "
        << settingsText(choice.pick().settings) << "\n";
}

QJsonObject choiceJson(const MethodChoice& choice, const AccuracyTolerance& tolerance) {
  QJsonArray candidates;
  for (const PilotMeasure& m : choice.candidates)
    candidates.append(QJsonObject{
        {"method", text(methodName(m.settings.method))},
        {"integrator", text(integratorName(m.settings.integrator))},
        {"timeStep", m.settings.timeStep},
        {"simulated", m.simulated},
        {"computeSeconds", m.computeSeconds},
        {"costPerSecond", m.costPerSecond},
        {"energyErrorPerSecond",
         std::isfinite(m.energyErrorPerSecond) ? QJsonValue(m.energyErrorPerSecond) : QJsonValue()},
        {"penetrationFraction", m.penetrationFraction},
        {"escaped", m.escaped},
        {"meets", m.meets},
        {"verdict", QString::fromStdString(m.verdict)}});
  QJsonObject json{
      {"tolerance", QJsonObject{{"energyPerSecond", tolerance.energyPerSecond},
                                {"penetrationFraction", tolerance.penetrationFraction}}},
      {"pilotSeconds", choice.pilotSeconds},
      {"pilotSimulated", choice.pilotSimulated},
      {"candidates", candidates},
      {"met", choice.chosen.has_value()},
      {"reason", QString::fromStdString(choice.reason)}};
  if (!choice.candidates.empty()) {
    json["chosen"] = static_cast<int>(choice.chosen.value_or(choice.closest));
    json["expectedRunSeconds"] = choice.expectedRunSeconds();
  }
  return json;
}

}  // namespace carom::cli
