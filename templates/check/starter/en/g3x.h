/* g3x.h: space's types and helpers, for the course's closing questions (the sphere, the cube),
 * in the spirit of the g3x library. Everything is defined here. */
#ifndef EPURE_G3X_H
#define EPURE_G3X_H

#include "g2x.h"

typedef struct {
  double x, y, z;
} G3Xcoord;
typedef G3Xcoord G3Xpoint;
typedef G3Xcoord G3Xvector;

/* AB = B - A */
static inline G3Xvector g3x_SetVect(G3Xpoint A, G3Xpoint B) { return (G3Xvector){B.x - A.x, B.y - A.y, B.z - A.z}; }
static inline G3Xvector g3x_AddVect(G3Xvector U, G3Xvector V) { return (G3Xvector){U.x + V.x, U.y + V.y, U.z + V.z}; }
static inline G3Xvector g3x_SubVect(G3Xvector U, G3Xvector V) { return (G3Xvector){U.x - V.x, U.y - V.y, U.z - V.z}; }
/* k * U */
static inline G3Xvector g3x_mapscal3(G3Xvector U, double k) { return (G3Xvector){k * U.x, k * U.y, k * U.z}; }
/* U.V, the dot product */
static inline double g3x_ProdScal(G3Xvector U, G3Xvector V) { return U.x * V.x + U.y * V.y + U.z * V.z; }
/* U^V, the cross product (a vector) */
static inline G3Xvector g3x_ProdVect(G3Xvector U, G3Xvector V) {
  return (G3Xvector){U.y * V.z - U.z * V.y, U.z * V.x - U.x * V.z, U.x * V.y - U.y * V.x};
}
/* ||V||^2 and ||V|| */
static inline double g3x_SqrNorm(G3Xvector V) { return V.x * V.x + V.y * V.y + V.z * V.z; }
static inline double g3x_Norm(G3Xvector V) { return sqrt(V.x * V.x + V.y * V.y + V.z * V.z); }
/* V divided by its length, in place (the zero vector is left as it is) */
static inline void g3x_Normalize(G3Xvector* V) {
  double n = sqrt(V->x * V->x + V->y * V->y + V->z * V->z);
  if (n > 0.) {
    V->x /= n;
    V->y /= n;
    V->z /= n;
  }
}

#endif
