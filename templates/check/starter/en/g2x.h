/* g2x.h: the plane's types and helpers as the course's code uses them (written for epure, in the
 * spirit of the g2x library: same names, same meaning). Everything is defined here: a file that
 * includes it compiles on its own, `gcc -std=c11 -Wall -Wextra -c raytracer.c`. */
#ifndef EPURE_G2X_H
#define EPURE_G2X_H

#include <math.h>
#include <stdbool.h>

/* A point and a vector of the plane have the same coordinates: one type, two names, as in g2x
 * (so that the course's (G2Xvector)A is a vector with A's coordinates). */
typedef struct {
  double x, y;
} G2Xcoord;
typedef G2Xcoord G2Xpoint;
typedef G2Xcoord G2Xvector;

#define SQR(a) ((a) * (a))
#define MIN(a, b) (((a) < (b)) ? (a) : (b))
#define MAX(a, b) (((a) < (b)) ? (b) : (a))

/* Instead of an equality test on doubles ("TEST d'EGALITE A PROSCRIRE"): a value this close to 0
 * is 0. An absolute threshold, meant for data of the order of 1 (the sheets' data lie within
 * ±10, with two decimals): their cross products are at least 1e-4 when not zero, and rounding
 * leaves at most about 1e-13 where they are zero in decimals. */
#define G2Xzero 1.e-10
#define G2Xiszero(x) ((((x) < G2Xzero) && ((x) > -G2Xzero)) ? true : false)

/* AB = B - A */
static inline G2Xvector g2x_SetVect(G2Xpoint A, G2Xpoint B) { return (G2Xvector){B.x - A.x, B.y - A.y}; }
static inline G2Xvector g2x_AddVect(G2Xvector U, G2Xvector V) { return (G2Xvector){U.x + V.x, U.y + V.y}; }
static inline G2Xvector g2x_SubVect(G2Xvector U, G2Xvector V) { return (G2Xvector){U.x - V.x, U.y - V.y}; }
/* k * U */
static inline G2Xvector g2x_mapscal2(G2Xvector U, double k) { return (G2Xvector){k * U.x, k * U.y}; }
/* U.V, the dot product */
static inline double g2x_ProdScal(G2Xvector U, G2Xvector V) { return U.x * V.x + U.y * V.y; }
/* U^V = xU.yV - yU.xV, the cross product in the plane (a number) */
static inline double g2x_ProdVect(G2Xvector U, G2Xvector V) { return U.x * V.y - U.y * V.x; }
/* ||V||^2 and ||V|| */
static inline double g2x_SqrNorm(G2Xvector V) { return V.x * V.x + V.y * V.y; }
static inline double g2x_Norm(G2Xvector V) { return sqrt(V.x * V.x + V.y * V.y); }
/* ||AB||^2 and ||AB|| */
static inline double g2x_SqrDist(G2Xpoint A, G2Xpoint B) { return SQR(B.x - A.x) + SQR(B.y - A.y); }
static inline double g2x_Dist(G2Xpoint A, G2Xpoint B) { return sqrt(SQR(B.x - A.x) + SQR(B.y - A.y)); }
/* V divided by its length, in place (the zero vector is left as it is) */
static inline void g2x_Normalize(G2Xvector* V) {
  double n = sqrt(V->x * V->x + V->y * V->y);
  if (n > 0.) {
    V->x /= n;
    V->y /= n;
  }
}

#endif
