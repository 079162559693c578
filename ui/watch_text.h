#pragma once
// The run watch's events in the program's language, for the status bar and the dialog.

#include "sim/measure/run_watch.h"
#include "sim/model/scene.h"

#include <QString>

namespace carom::ui {

// What happened, to which ball (by its name when it has one) and when, as a sentence.
QString watchEventText(const carom::WatchEvent& event, const carom::Scene& scene);

}  // namespace carom::ui
