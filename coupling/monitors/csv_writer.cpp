#include "coupling/monitors/csv_writer.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>

#include "cfd/base/config_error.hpp"
#include "cfd/base/internal_error.hpp"

namespace parcelflow::coupling {

namespace {

std::string headerLine(const std::vector<std::string>& columns) {
  std::string line;
  for (std::size_t c = 0; c < columns.size(); ++c) line += (c ? "," : "") + columns[c];
  return line + "\n";
}

}  // namespace

CsvWriter::CsvWriter(const std::string& path, const std::vector<std::string>& columns, bool is_writer_rank)
    : path_(path), ncolumns_(columns.size()) {
  if (!is_writer_rank) return;
  file_ = std::fopen(path.c_str(), "w");
  if (!file_) throw std::runtime_error("cannot write '" + path + "': " + std::strerror(errno));
  unbuffered();
  put(headerLine(columns));
}

CsvWriter::CsvWriter(const std::string& path, const std::vector<std::string>& columns, bool is_writer_rank,
                     long bytes)
    : path_(path), ncolumns_(columns.size()) {
  if (!is_writer_rank) return;
  std::ifstream in(path);
  std::string header;
  if (!in || !std::getline(in, header))
    throw cfd::ConfigError(path, "missing or empty", "the monitors.csv the checkpoint's run wrote");
  if (header + "\n" != headerLine(columns))
    throw cfd::ConfigError(path, "columns " + header,
                           "the columns this case writes: " + headerLine(columns).substr(0, headerLine(columns).size() - 1));
  in.seekg(0, std::ios::end);
  if (static_cast<long>(in.tellg()) < bytes)
    throw cfd::ConfigError(path, std::to_string(static_cast<long>(in.tellg())) + " bytes",
                           "at least the " + std::to_string(bytes) + " bytes written at the checkpoint");
  in.close();
  if (truncate(path.c_str(), bytes) != 0) throw std::runtime_error("cannot cut '" + path + "': " + std::strerror(errno));
  file_ = std::fopen(path.c_str(), "a");
  if (!file_) throw std::runtime_error("cannot append to '" + path + "': " + std::strerror(errno));
  unbuffered();
  bytes_ = bytes;
}

CsvWriter::~CsvWriter() {
  if (file_) std::fclose(file_);
}

// Every row goes to the file at once, so after a failed write no part of it waits in a buffer that a later
// flush (at exit) could append behind the cut.
void CsvWriter::unbuffered() { std::setvbuf(file_, nullptr, _IONBF, 0); }

void CsvWriter::put(const std::string& text) {
  if (std::fputs(text.c_str(), file_) < 0 || std::fflush(file_) != 0) {
    const int error = errno;
    // Keep only complete rows: cut what part of this one reached the file (if even that fails, the message
    // says so).
    const bool cut = ftruncate(fileno(file_), bytes_) == 0;
    throw std::runtime_error("writing '" + path_ + "' failed: " + std::strerror(error) +
                             (cut ? "; it keeps its complete rows (" : "; cutting it back to its complete rows (") +
                             std::to_string(bytes_) + (cut ? " bytes)" : " bytes) failed too"));
  }
  bytes_ += static_cast<long>(text.size());
}

void CsvWriter::row(const std::vector<double>& values) {
  PARCELFLOW_ASSERT(values.size() == ncolumns_, "CsvWriter: " + std::to_string(values.size()) + " values for " +
                                                    std::to_string(ncolumns_) + " columns of " + path_);
  ++rows_;
  if (!file_) return;
  std::string line;
  char buf[32];
  for (std::size_t c = 0; c < values.size(); ++c) {
    std::snprintf(buf, sizeof buf, "%s%.10g", c ? "," : "", values[c]);
    line += buf;
  }
  put(line + "\n");
}

}  // namespace parcelflow::coupling
