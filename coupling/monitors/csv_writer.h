// A CSV time series written by rank 0: fixed columns named at creation, one row per call, flushed so that a
// run that is stopped keeps every row written so far. A failed write throws at once (a full disk must not
// cut rows silently).
#pragma once

#include <cstdio>
#include <string>
#include <vector>

namespace parcelflow::coupling {

class CsvWriter {
 public:
  // A new file with the header line.
  CsvWriter(const std::string& path, const std::vector<std::string>& columns, bool is_writer_rank);
  // Continues an existing file: its header must be `columns`; it is cut back to `bytes` (what had been
  // written at a checkpoint), so rows written after that checkpoint are not duplicated. Throws
  // cfd::ConfigError naming the file when it is missing, shorter, or has other columns.
  CsvWriter(const std::string& path, const std::vector<std::string>& columns, bool is_writer_rank, long bytes);
  ~CsvWriter();
  CsvWriter(const CsvWriter&) = delete;
  CsvWriter& operator=(const CsvWriter&) = delete;

  void row(const std::vector<double>& values);  // must match the columns
  const std::string& path() const { return path_; }
  long bytes() const { return bytes_; }  // written so far (rank 0; 0 elsewhere)
  long rows() const { return rows_; }

 private:
  void unbuffered();
  void put(const std::string& text);
  std::string path_;
  std::size_t ncolumns_;
  std::FILE* file_ = nullptr;
  long bytes_ = 0, rows_ = 0;
};

}  // namespace parcelflow::coupling
