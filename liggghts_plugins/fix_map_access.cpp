// Why this file exists
// --------------------
// LIGGGHTS 3.8.0 has no plugin API: fix styles are looked up in `Modify::fix_map`, a PRIVATE member
// filled at construction from the compiled-in style list. Debian ships LIGGGHTS as an unmodifiable
// shared library, so the only way to add our fix styles at run time is to insert creators into that map.
//
// Why it is legal C++
// -------------------
// C++17 [temp.explicit] (paragraph 14 of N4659; [temp.spec.general] in C++20): "The usual access checking
// rules do not apply to names used to specify explicit instantiations." So an explicit instantiation may take the address
// &Modify::fix_map as a template argument. The instantiated class template defines a friend function
// that returns that member pointer; the friend is found through argument-dependent lookup on a tag type.
// No cast, no layout assumption, no undefined behaviour: this is the standard "access via explicit
// instantiation" idiom. Keep it in this one file; nothing else in parcelflow touches private members.
#include "liggghts_plugins/fix_map_access.h"

#include "lammps.h"
#include "modify.h"

namespace parcelflow::plugins {
namespace {

struct ModifyFixMapTag {
  using type = std::map<std::string, FixCreator>* LAMMPS_NS::Modify::*;
  friend type member_pointer(ModifyFixMapTag);
};

template <class Tag, typename Tag::type Member>
struct MemberPointerExporter {
  friend typename Tag::type member_pointer(Tag) { return Member; }
};

// The explicit instantiation: the only place where the private name is used.
template struct MemberPointerExporter<ModifyFixMapTag, &LAMMPS_NS::Modify::fix_map>;

}  // namespace

std::map<std::string, FixCreator>& fix_map(LAMMPS_NS::LAMMPS* lmp)
{
  return *(lmp->modify->*member_pointer(ModifyFixMapTag{}));
}

}  // namespace parcelflow::plugins
