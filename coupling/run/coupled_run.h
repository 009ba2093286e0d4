// A coupled CFD-DEM run of one case folder: the gas solver and LIGGGHTS on all ranks, one time loop.
// The API follows preCICE's shape: initialize() reads and checks everything and starts both codes,
// advance() does one coupling step, finalize() writes the last output and the summary.
//
// One coupling step (t -> t + dt_gas), staggered:
//   1. parcels at t -> solids fraction a_s on the mesh (Gaussian kernel, conservative across ranks);
//   2. gas fraction and gas velocity at t at the parcels -> drag law (real diameter) -> kappa per parcel,
//      deposited as beta and beta u_s;
//   3. gas advances to t + dt with a_g = max(1 - a_s, floor) (floor hits counted), beta, beta u_s;
//   4. gas velocity and pressure gradient at t + dt gathered at the parcels;
//   5. LIGGGHTS advances its DEM substeps with kappa, u_f and -np V_p grad p held fixed (implicit drag).
// Then the outputs that are due (monitors, fields, parcels, checkpoint), and a stop signal on any rank ends
// the loop after a checkpoint.
#pragma once

#include <memory>
#include <string>

namespace parcelflow::coupling {

struct RunOptions {
  std::string case_folder;
  std::string output_folder;  // default: CASE/output
  double end_time = 0.0;      // > 0 replaces time.end of case.yaml
  std::string restart;        // a checkpoint folder to continue from (empty: a fresh start)
};

class CoupledRun {
 public:
  explicit CoupledRun(const RunOptions& options);
  ~CoupledRun();

  void initialize();
  bool advance();  // false once the end time is reached or a stop signal was handled
  void finalize();

  // After advance() returned false: the signal that stopped the run (0: it reached its end) and the
  // checkpoint written then.
  int stopSignal() const;
  std::string lastCheckpoint() const;

  struct State;

 private:
  std::unique_ptr<State> s_;
};

}  // namespace parcelflow::coupling
