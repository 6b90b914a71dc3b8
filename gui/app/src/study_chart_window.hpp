// The atlas in the desktop program: a study's CSV (`styk study accuracy|stability`) as
// interactive Qt Charts, the same charts the study draws into its pictures (styk_study_results'
// chart descriptions, styk_charts' drawing): choose the problem, the error measure and the axis;
// zoom with a rubber band, rest the mouse on a point to read its run, click a legend entry to
// hide or show that family.
#pragma once

#include <QDialog>
#include <QString>
#include <vector>

#include "styk/studies/results/run_record.hpp"

class QChartView;
class QComboBox;
class QLabel;

namespace styk::gui {

class StudyChartWindow : public QDialog {
  Q_OBJECT
 public:
  // `records` as read from `source` (a path, shown in the title).
  StudyChartWindow(std::vector<studies::RunRecord> records, const QString& source,
                   QWidget* parent = nullptr);

  QChartView* chart_view() const { return view_; }
  // Selects by the combo boxes' texts (problem name, measure label, axis label); false if one is
  // not offered.
  bool show_chart(const QString& problem, const QString& measure, const QString& axis);
  // The tip of the point last hovered (what the status line shows).
  QString hovered_tip() const;
  // The tip of point `index` of the series named `series` (for tests: what hovering it shows).
  QString tip_of(const QString& series, int index) const;

 private:
  void fill_measures_and_axes();
  void redraw();
  void connect_series();

  std::vector<studies::RunRecord> records_;
  std::vector<std::string> families_;
  QComboBox* problem_ = nullptr;
  QComboBox* measure_ = nullptr;
  QComboBox* axis_ = nullptr;
  QChartView* view_ = nullptr;
  QLabel* status_ = nullptr;
};

}  // namespace styk::gui
