// Debian's libliggghts-dev does not ship the build-generated list of contact models. The LIGGGHTS
// headers pair_gran.h / fix_wall_gran.h include it only to define model-id constants, which parcelflow
// does not use (it asks the model by name through the virtual contact_match()). Empty on purpose.
