#include "ui/watch_text.h"

#include "ui/editor/number_text.h"
#include "ui/editor/object_ref.h"

#include <QCoreApplication>
#include <QFont>
#include <QGuiApplication>

namespace carom::ui {
namespace {

QString tr(const char* text) {
  return QCoreApplication::translate("WatchText", text);
}

// The status bar and the dialog show these in the application's font.
QString shownName(const std::string& name) {
  return editor::elidedName(QString::fromStdString(name), QGuiApplication::font());
}

QString ballName(int ball, const Scene& scene) {
  if (ball >= 0 && ball < int(scene.balls.size()) && !scene.balls[ball].name.empty())
    return tr("ball %1 (%2)").arg(ball).arg(shownName(scene.balls[ball].name));
  return tr("ball %1").arg(ball);
}

QString otherName(const WatchEvent& event, const Scene& scene) {
  const auto named = [](const QString& plain, const std::string& name) {
    return name.empty() ? plain : plain + QString(" (%1)").arg(shownName(name));
  };
  const int i = event.other;
  switch (event.otherKind) {
    case WatchOther::None:
      return {};
    case WatchOther::Ball:
      return ballName(i, scene);
    case WatchOther::Plane:
      return named(tr("plane %1").arg(i), i < int(scene.planes.size()) ? scene.planes[i].name : "");
    case WatchOther::Cylinder:
      return named(tr("cylinder %1").arg(i),
                   i < int(scene.cylinders.size()) ? scene.cylinders[i].name : "");
    case WatchOther::Box:
      return named(tr("box %1").arg(i), i < int(scene.boxes.size()) ? scene.boxes[i].name : "");
  }
  return {};
}

}  // namespace

QString watchEventText(const WatchEvent& event, const Scene& scene) {
  const QString ball = ballName(event.ball, scene);
  const QString time = editor::formatShortNumber(event.time);
  const QString value = editor::formatShortNumber(event.value);
  const QString tolerance = editor::formatShortNumber(event.tolerance);
  switch (event.kind) {
    case WatchKind::NonFinite:
      return tr("At %1 s %2 has a position or velocity that is not a finite number.")
          .arg(time, ball);
    case WatchKind::EnergyRise:
      return tr("At %1 s the energy rose by %2 of the scene's energy scale (tolerance %3); "
                "%4 gained the most.")
          .arg(time, value, tolerance, ball);
    case WatchKind::Escape:
      return tr("At %1 s %2 got inside %3: its centre is %4 of its radius past the surface.")
          .arg(time, ball, otherName(event, scene), value);
    case WatchKind::Penetration:
      return tr("At %1 s %2 overlaps %3 by %4 of the radius (tolerance %5).")
          .arg(time, ball, otherName(event, scene), value, tolerance);
  }
  return {};
}

}  // namespace carom::ui
