#pragma once
// What `--method auto` tried and chose, as text or JSON, for the run's report.

#include "sim/measure/method_choice.h"

#include <QJsonObject>
#include <QTextStream>

namespace carom::cli {

// One line per candidate (settings, cost, measures, verdict), then the choice and why.
void printChoice(QTextStream& out, const MethodChoice& choice, const AccuracyTolerance& tolerance);
QJsonObject choiceJson(const MethodChoice& choice, const AccuracyTolerance& tolerance);
// "swept (velocity-verlet, dt 0.004 s)", "exact".
QString settingsText(const StudyCase& settings);

}  // namespace carom::cli
