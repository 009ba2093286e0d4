// A CSV time series written by rank 0: fixed columns named at creation, one row per call, flushed so
// that a run that is stopped keeps every row written so far.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

namespace parcelflow::coupling {

class CsvWriter {
 public:
  CsvWriter(const std::string& path, const std::vector<std::string>& columns, bool is_writer_rank);
  ~CsvWriter();
  CsvWriter(const CsvWriter&) = delete;
  CsvWriter& operator=(const CsvWriter&) = delete;

  void row(const std::vector<double>& values);  // must match the columns
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  std::size_t ncolumns_;
  std::FILE* file_ = nullptr;
};

}  // namespace parcelflow::coupling
