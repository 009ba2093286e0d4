// monitors.csv: the column `time` and then the columns of every monitor, in order; one row per sample.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "coupling/monitors/csv_writer.h"
#include "coupling/monitors/monitor.h"

namespace parcelflow::coupling {

class MonitorTable {
 public:
  // A new monitors.csv at `path` (rank 0 writes), or with resume_bytes >= 0 the continuation of one that
  // had that many bytes at a checkpoint.
  MonitorTable(std::vector<std::unique_ptr<Monitor>> monitors, const std::string& path, bool is_writer_rank,
               long resume_bytes = -1);
  void sample(const MonitorInput& in);  // collective
  const CsvWriter& csv() const { return *csv_; }

 private:
  std::vector<std::unique_ptr<Monitor>> monitors_;
  std::vector<std::size_t> widths_;
  std::unique_ptr<CsvWriter> csv_;
};

}  // namespace parcelflow::coupling
