/* rulemesh.h: the umbrella header of rulemesh's C decoders, for Swift
 * (module.modulemap makes it the module RulemeshC) and for anything that
 * wants both decoders with one include:
 *   - rulemesh_scene.h:  the `scene` format (what the grammar placed;
 *                        the smallest payload) into meshes;
 *   - rulemesh_strips.h: the `strips` format (quantised, meshopt-coded
 *                        triangle strips) into vertex and index arrays.
 * Both are C99, allocate nothing and keep no global state. Compile
 * rulemesh_scene.c and rulemesh_strips.c with the app (the .inc files beside
 * rulemesh_scene.c are included by it, not compiled on their own).
 * clients/c/README.md has the Swift, Kotlin/Native and NDK notes.
 */
#ifndef RULEMESH_H
#define RULEMESH_H

#include "rulemesh_scene.h"
#include "rulemesh_strips.h"

#endif /* RULEMESH_H */
