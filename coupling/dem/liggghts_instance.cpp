#include "coupling/dem/liggghts_instance.h"

#include <csignal>
#include <cstring>
#include <string>

#include "coupling/dem/contact_time_check.h"
#include "input.h"
#include "lammps.h"
#include "signal_handling.h"

namespace parcelflow::coupling {

namespace {

// A FILE* (glibc cookie stream) that forwards complete lines with ERROR or WARNING to stdout.
struct LineFilter {
  std::string pending;
};

ssize_t filterWrite(void* cookie, const char* data, size_t size) {
  auto* filter = static_cast<LineFilter*>(cookie);
  filter->pending.append(data, size);
  std::size_t end;
  while ((end = filter->pending.find('\n')) != std::string::npos) {
    const std::string line = filter->pending.substr(0, end + 1);
    if (line.find("ERROR") != std::string::npos || line.find("WARNING") != std::string::npos)
      std::fputs(line.c_str(), stdout);
    filter->pending.erase(0, end + 1);
  }
  return static_cast<ssize_t>(size);
}

int filterClose(void* cookie) {
  delete static_cast<LineFilter*>(cookie);
  return 0;
}

}  // namespace

LiggghtsInstance::LiggghtsInstance(MPI_Comm world, const std::vector<std::string>& arguments) {
  MPI_Comm_dup(world, &comm_);
  std::vector<std::string> storage;
  storage.reserve(arguments.size() + 1);
  storage.emplace_back("parcelflow");
  storage.insert(storage.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (auto& s : storage) argv.push_back(s.data());
  argv.push_back(nullptr);
  lmp_ = new LAMMPS_NS::LAMMPS(static_cast<int>(storage.size()), argv.data(), comm_);
}

LiggghtsInstance::~LiggghtsInstance() {
  delete lmp_;
  if (filtered_screen_) std::fclose(filtered_screen_);
  MPI_Comm_free(&comm_);
}

void LiggghtsInstance::runInputFile() { lmp_->input->file(); }

namespace {

// fix parcel/implicit_drag's check at the start of a run, as the user error it is
template <class Commands>
void withDemStepCheck(Commands&& commands) {
  try {
    commands();
  } catch (const plugins::DemStepTooLong& e) {
    throw demStepError("time.dem_step", e.estimate, e.dem_step,
                       "found at the start of a LIGGGHTS run at DEM step " + std::to_string(e.step) +
                           " (before it moved any atom)");
  }
}

}  // namespace

void LiggghtsInstance::runFile(const std::string& path) {
  withDemStepCheck([&] { lmp_->input->file(path.c_str()); });
}

void LiggghtsInstance::command(const std::string& line) {
  withDemStepCheck([&] { lmp_->input->one(line.c_str()); });
}

void LiggghtsInstance::quietCommand(const std::string& line) {
  if (!lmp_->screen) return command(line);  // this rank prints nothing anyway
  if (!filtered_screen_) {
    filtered_screen_ = fopencookie(new LineFilter, "w", cookie_io_functions_t{nullptr, filterWrite, nullptr, filterClose});
    std::setvbuf(filtered_screen_, nullptr, _IONBF, 0);  // LIGGGHTS may exit right after an ERROR line
  }
  std::FILE* screen = lmp_->screen;
  lmp_->screen = filtered_screen_;
  command(line);
  lmp_->screen = screen;
}

void LiggghtsInstance::installSignalHandlers() {
  struct sigaction interrupt {};
  interrupt.sa_handler = LAMMPS_NS::SignalHandler::int_handler;
  sigaction(SIGINT, &interrupt, nullptr);
  // Open MPI turns a SIGINT to mpirun into SIGTERM to its children: treat both alike.
  sigaction(SIGTERM, &interrupt, nullptr);
  struct sigaction restart {};
  restart.sa_handler = LAMMPS_NS::SignalHandler::usr1_handler;
  sigaction(SIGUSR1, &restart, nullptr);
}

}  // namespace parcelflow::coupling
