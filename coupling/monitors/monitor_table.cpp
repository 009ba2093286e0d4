#include "coupling/monitors/monitor_table.h"

#include <mpi.h>

#include "coupling/run/broadcast_text.h"
#include "cfd/base/config_error.hpp"
#include "cfd/base/internal_error.hpp"

namespace parcelflow::coupling {

MonitorTable::MonitorTable(std::vector<std::unique_ptr<Monitor>> monitors, const std::string& path,
                           bool is_writer_rank, long resume_bytes)
    : monitors_(std::move(monitors)) {
  std::vector<std::string> columns = {"time"};
  for (const auto& m : monitors_) {
    const std::vector<std::string> names = m->columns();
    widths_.push_back(names.size());
    columns.insert(columns.end(), names.begin(), names.end());
  }
  if (resume_bytes < 0) {
    csv_ = std::make_unique<CsvWriter>(path, columns, is_writer_rank);
    return;
  }
  // Only the writer rank looks at the file; all ranks stop together if it does not fit.
  std::string error;
  try {
    csv_ = std::make_unique<CsvWriter>(path, columns, is_writer_rank, resume_bytes);
  } catch (const cfd::ConfigError& e) {
    error = e.what();
  }
  error = broadcastText(error, 0, MPI_COMM_WORLD);  // only the writer rank (0) opened the file
  if (!error.empty()) throw cfd::ConfigError(error);
}

void MonitorTable::sample(const MonitorInput& in) {
  std::vector<double> row = {in.time};
  for (std::size_t k = 0; k < monitors_.size(); ++k) {
    const std::size_t before = row.size();
    monitors_[k]->sample(in, row);
    PARCELFLOW_ASSERT(row.size() - before == widths_[k], "a monitor wrote another number of values than its columns");
  }
  csv_->row(row);
}

}  // namespace parcelflow::coupling
