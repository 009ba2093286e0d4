#include "csv_writer.h"

#include <stdexcept>

namespace parcelflow::coupling {

CsvWriter::CsvWriter(const std::string& path, const std::vector<std::string>& columns, bool is_writer_rank)
    : path_(path), ncolumns_(columns.size()) {
  if (!is_writer_rank) return;
  file_ = std::fopen(path.c_str(), "w");
  if (!file_) throw std::runtime_error("cannot write '" + path + "'");
  for (std::size_t c = 0; c < columns.size(); ++c) std::fprintf(file_, "%s%s", c ? "," : "", columns[c].c_str());
  std::fprintf(file_, "\n");
  std::fflush(file_);
}

CsvWriter::~CsvWriter() {
  if (file_) std::fclose(file_);
}

void CsvWriter::row(const std::vector<double>& values) {
  if (values.size() != ncolumns_)
    throw std::logic_error("CsvWriter: " + std::to_string(values.size()) + " values for " + std::to_string(ncolumns_) +
                           " columns of " + path_);
  if (!file_) return;
  for (std::size_t c = 0; c < values.size(); ++c) std::fprintf(file_, "%s%.10g", c ? "," : "", values[c]);
  std::fprintf(file_, "\n");
  std::fflush(file_);
}

}  // namespace parcelflow::coupling
