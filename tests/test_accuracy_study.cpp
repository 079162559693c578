// The study's measures: distances of distributions on closed-form samples, the sample times, and
// the agreement horizon on a scene with no chaos (one ball, which the finest setting follows to
// the end) and on one with plenty (a gas, which every approximate method leaves).

#include "sim/measure/accuracy_study.h"
#include "sim/measure/measures.h"
#include "sim/model/scene_builders.h"

#include <QtTest>

#include <cmath>
#include <vector>

using carom::Integrator;
using carom::Method;
using carom::StudyCase;
using carom::StudyReference;
using carom::StudyResult;

namespace {

double meanRadius(const carom::Scene& scene) {
  double sum = 0.0;
  for (const carom::Ball& ball : scene.balls) sum += ball.radius;
  return sum / double(scene.balls.size());
}

}  // namespace

class TestAccuracyStudy : public QObject {
  Q_OBJECT

 private slots:
  void distributionDistanceClosedForms() {
    using carom::distributionDistance;
    QCOMPARE(distributionDistance({1, 2, 3}, {3, 1, 2}), 0.0);  // the same values
    QCOMPARE(distributionDistance({1, 2}, {3, 4}), 1.0);        // no overlap
    // F_a - F_b peaks after 2: a has 2 of 4 there, b none.
    QCOMPARE(distributionDistance({1, 2, 3, 4}, {3, 4, 5, 6}), 0.5);
    // Ties between the samples add no gap: {1,1,2} against {1,2,2} differ by 1/3 at 1.
    QCOMPARE(distributionDistance({1, 1, 2}, {1, 2, 2}), 1.0 / 3.0);
    // Samples of different sizes from the same even spread.
    QCOMPARE(distributionDistance({0, 1}, {0, 0, 1, 1}), 0.0);
    // A NaN counts as larger than everything, not as a crash or a silent zero: {1, NaN} against
    // {1, 2} differs by 1/2 between 2 and the NaN.
    QCOMPARE(distributionDistance({std::nan(""), 1.0}, {1.0, 2.0}), 0.5);
    QCOMPARE(distributionDistance({std::nan(""), std::nan("")}, {1.0, 2.0}), 1.0);
  }

  void sampleTimesSpreadOnALogScale() {
    const std::vector<double> times = carom::studySampleTimes(5.0, 100);
    QCOMPARE(times.size(), carom::kStudySamples);
    QCOMPARE(times.back(), 5.0);
    QVERIFY(std::abs(times.front() - 5.0 * carom::kFirstSampleFraction) < 1e-15);
    const double ratio = times[1] / times[0];
    for (std::size_t k = 1; k < times.size(); ++k) {
      QVERIFY(times[k] > times[k - 1]);
      QVERIFY(std::abs(times[k] / times[k - 1] - ratio) < 1e-9);
    }
    // Many balls: fewer samples, within the memory budget, still ending at the duration.
    const std::size_t many = 4'000'000;
    const std::vector<double> few = carom::studySampleTimes(5.0, many);
    QVERIFY(few.size() < carom::kStudySamples);
    QVERIFY(few.size() * many * sizeof(carom::Vec3) <= carom::kStudySampleBudgetBytes);
    QCOMPARE(few.back(), 5.0);
  }

  void oneBallAgreesToTheEnd() {
    // A ball bouncing on a floor: swept with velocity Verlet follows each parabola up to
    // round-off and meets the floor within a millimetre or so (its contact times come from
    // chords), well within a tenth of the radius, so the horizon is the whole run.
    carom::Scene scene;
    scene.world.timeStep = 1.0 / 60.0;
    carom::Plane floor;
    floor.normal = carom::Vec3(0, 1, 0);
    scene.planes.push_back(floor);
    carom::Ball ball;
    ball.radius = 0.5;
    ball.position = carom::Vec3(0, 1.5, 0);
    ball.velocity = carom::Vec3(0.3, 0, 0);
    scene.balls.push_back(ball);
    const double duration = 2.0;
    StudyReference reference = carom::exactReference(scene, duration);
    QCOMPARE(reference.positions.size(), reference.sampleTimes.size());
    const std::vector<StudyCase> cases = carom::studyCases(scene.world, carom::kStudyStepFactors);
    const std::optional<std::size_t> finest = carom::finestCase(cases);
    QVERIFY(finest);
    QCOMPARE(cases[*finest].method, Method::Swept);
    QCOMPARE(cases[*finest].integrator, Integrator::VelocityVerlet);
    QCOMPARE(cases[*finest].timeStep, scene.world.timeStep * 0.25);
    const StudyResult fine =
        carom::runStudyCase(scene, cases[*finest], duration, reference, nullptr);
    carom::setAgreementHorizon(reference, fine, meanRadius(scene));
    QCOMPARE(reference.horizon(), std::optional<double>(duration));
    // The exact case repeats the reference bit for bit.
    const StudyResult exact = carom::runStudyCase(scene, cases[0], duration, reference, nullptr);
    QCOMPARE(exact.deviation.size(), reference.sampleTimes.size());
    for (double d : exact.deviation) QCOMPARE(d, 0.0);
    QCOMPARE(exact.positionError, 0.0);
    QCOMPARE(exact.speedDistribution, 0.0);
    // Coarse discrete steps bounce late and land off the parabola.
    const StudyResult coarse = carom::runStudyCase(
        scene, {Method::Discrete, Integrator::ExplicitEuler, 4.0 * scene.world.timeStep}, duration,
        reference, nullptr);
    QVERIFY(coarse.positionError > 1e-3);
  }

  void gasPartsBeforeTheEnd() {
    // 64 balls in a box: collisions amplify every difference, and after a few seconds even the
    // finest setting is somewhere else; the horizon falls short of the run, and position errors
    // are taken there, where they still differ from one setting to the next.
    const carom::Scene scene = carom::makeGasInBox(64, 0.2, carom::Vec3::Zero(), 3);
    const double duration = 10.0;
    StudyReference reference = carom::exactReference(scene, duration);
    const std::vector<StudyCase> cases = carom::studyCases(scene.world, carom::kStudyStepFactors);
    const StudyResult fine =
        carom::runStudyCase(scene, cases[*carom::finestCase(cases)], duration, reference, nullptr);
    QVERIFY(fine.deviation.back() > carom::kAgreementRadiusFraction * meanRadius(scene));
    carom::setAgreementHorizon(reference, fine, meanRadius(scene));
    QVERIFY(reference.horizon());
    QVERIFY(*reference.horizon() < duration);
    QVERIFY(*reference.horizon() > 0.0);
    const StudyResult coarse = carom::runStudyCase(
        scene, {Method::Discrete, Integrator::SymplecticEuler, 4.0 * scene.world.timeStep},
        duration, reference, nullptr);
    QVERIFY(!std::isnan(coarse.positionError));
    // At the end the coarse run is lost in the chaos, as far off as the finest one; at the
    // horizon it is measurably worse than the finest.
    QVERIFY(coarse.positionError < coarse.deviation.back());
    QVERIFY(coarse.positionError > fine.deviation[*reference.horizonSample]);
    // The distributions of a gas survive the chaos: each far from 1.
    QVERIFY(fine.speedDistribution < 0.5);
    QVERIFY(fine.positionDistribution < 0.5);
  }
};

QTEST_APPLESS_MAIN(TestAccuracyStudy)
#include "test_accuracy_study.moc"
