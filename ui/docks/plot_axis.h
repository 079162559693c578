#pragma once
// What the window's plots share so that they read well in a dock and in the user's language:
// ticks at round steps, labelled with as many decimals as the step needs, in the language's
// number format.

class QChart;
class QValueAxis;

namespace carom::ui {

// Gives the chart's room to its plot: a dock below the view is low, and a chart's own margins
// and rounded background took a third of its height, leaving the labels "...".
void fitToDock(QChart* chart);

// Writes the chart's numbers in the current language's format; again after a language change.
void localizeNumbers(QChart* chart);

// Shows `low` to `high` on `axis` with at most `maxTicks` ticks, at multiples of 1, 2, 2.5 or 5
// times a power of ten (0, 0.25, 0.5… rather than Qt's evenly cut range read to one decimal,
// "0.3" for 0.25).
void setRoundRange(QValueAxis* axis, double low, double high, int maxTicks);

}  // namespace carom::ui
