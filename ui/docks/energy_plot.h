#pragma once
// A live plot of kinetic, potential and total energy over simulated time, fed from snapshots.

#include <QList>
#include <QPointF>
#include <QTimer>
#include <QWidget>

class QChart;
class QLineSeries;
class QValueAxis;

namespace carom::ui {

struct SimulationSnapshot;

class EnergyPlot : public QWidget {
  Q_OBJECT
 public:
  explicit EnergyPlot(QWidget* parent = nullptr);

  // Adds the snapshot's energies; a snapshot earlier than the last one (a reset) starts over.
  void add(const SimulationSnapshot& snapshot);
  void clear();
  // Points drawn so far; added ones are drawn within a tenth of a second.
  int pointCount() const;

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void truncateAfter(double t);
  void retranslate();
  void drawPending();

  QChart* chart_;
  QLineSeries* kinetic_;
  QLineSeries* potential_;
  QLineSeries* total_;
  QValueAxis* timeAxis_;
  QValueAxis* energyAxis_;
  QList<QPointF> pending_[3];  // kinetic, potential, total: added but not yet drawn
  QTimer redrawTimer_;
  double lastTime_ = -1.0;
  double low_ = 0.0;
  double high_ = 0.0;
};

}  // namespace carom::ui
