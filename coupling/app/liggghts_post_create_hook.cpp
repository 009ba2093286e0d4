// Keeps parcelflow's LIGGGHTS styles registered for the whole life of every LIGGGHTS instance.
//
// Why this exists: LIGGGHTS 3.8 has no plugin API, and its input command `clear` destroys and re-creates
// the style registries (Modify, Force), so styles registered once after construction vanish. LIGGGHTS
// calls LAMMPS::post_create() right after it creates those registries, at construction and in every
// `clear`, and it calls it through the dynamic linker (a default-visibility function of libliggghts.so).
// Defining it here, in the executable, interposes it: we run LIGGGHTS' own post_create (looked up with
// dlsym(RTLD_NEXT)) and then register our styles, the moment the registries exist again. This is the
// ELF rule that the executable's definition wins, nothing more; tests/regression/dem/check_command_line.py
// checks it after `clear`.
#include <dlfcn.h>

#include <cstdio>
#include <cstdlib>

#include "lammps.h"
#include "liggghts_plugins/register_styles.h"

void LAMMPS_NS::LAMMPS::post_create() {
  using PostCreate = void (*)(LAMMPS_NS::LAMMPS*);
  static const auto liggghts_post_create =
      reinterpret_cast<PostCreate>(dlsym(RTLD_NEXT, "_ZN9LAMMPS_NS6LAMMPS11post_createEv"));
  if (!liggghts_post_create) {
    std::fprintf(stderr, "parcelflow: internal error: LAMMPS::post_create not found in libliggghts\n");
    std::abort();
  }
  liggghts_post_create(this);
  parcelflow::plugins::register_styles(this);
}
