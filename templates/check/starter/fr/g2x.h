/* g2x.h : les types et les outils du plan, tels que le code du cours les utilise (écrits pour
 * epure, dans l'esprit de la bibliothèque g2x : mêmes noms, même sens). Tout est défini ici : un
 * fichier qui l'inclut compile seul, `gcc -std=c11 -Wall -Wextra -c raytracer.c`. */
#ifndef EPURE_G2X_H
#define EPURE_G2X_H

#include <math.h>
#include <stdbool.h>

/* Un point et un vecteur du plan ont les mêmes coordonnées : un type, deux noms, comme dans g2x
 * (ainsi le (G2Xvector)A du cours est le vecteur de coordonnées celles de A). */
typedef struct {
  double x, y;
} G2Xcoord;
typedef G2Xcoord G2Xpoint;
typedef G2Xcoord G2Xvector;

#define SQR(a) ((a) * (a))
#define MIN(a, b) (((a) < (b)) ? (a) : (b))
#define MAX(a, b) (((a) < (b)) ? (b) : (a))

/* À la place d'un test d'égalité sur des réels (« TEST d'EGALITE A PROSCRIRE ») : une valeur aussi
 * proche de 0 est nulle. Un seuil absolu, fait pour des données de l'ordre de 1 (celles des
 * feuilles sont entre -10 et 10, à deux décimales) : leurs produits vectoriels valent au moins
 * 1e-4 quand ils ne sont pas nuls, et l'arrondi laisse au plus 1e-13 environ là où ils sont nuls
 * en décimal. */
#define G2Xzero 1.e-10
#define G2Xiszero(x) ((((x) < G2Xzero) && ((x) > -G2Xzero)) ? true : false)

/* AB = B - A */
static inline G2Xvector g2x_SetVect(G2Xpoint A, G2Xpoint B) { return (G2Xvector){B.x - A.x, B.y - A.y}; }
static inline G2Xvector g2x_AddVect(G2Xvector U, G2Xvector V) { return (G2Xvector){U.x + V.x, U.y + V.y}; }
static inline G2Xvector g2x_SubVect(G2Xvector U, G2Xvector V) { return (G2Xvector){U.x - V.x, U.y - V.y}; }
/* k * U */
static inline G2Xvector g2x_mapscal2(G2Xvector U, double k) { return (G2Xvector){k * U.x, k * U.y}; }
/* U.V, le produit scalaire */
static inline double g2x_ProdScal(G2Xvector U, G2Xvector V) { return U.x * V.x + U.y * V.y; }
/* U^V = xU.yV - yU.xV, le produit vectoriel dans le plan (un nombre) */
static inline double g2x_ProdVect(G2Xvector U, G2Xvector V) { return U.x * V.y - U.y * V.x; }
/* ||V||^2 et ||V|| */
static inline double g2x_SqrNorm(G2Xvector V) { return V.x * V.x + V.y * V.y; }
static inline double g2x_Norm(G2Xvector V) { return sqrt(V.x * V.x + V.y * V.y); }
/* ||AB||^2 et ||AB|| */
static inline double g2x_SqrDist(G2Xpoint A, G2Xpoint B) { return SQR(B.x - A.x) + SQR(B.y - A.y); }
static inline double g2x_Dist(G2Xpoint A, G2Xpoint B) { return sqrt(SQR(B.x - A.x) + SQR(B.y - A.y)); }
/* V divisé par sa longueur, sur place (le vecteur nul reste tel quel) */
static inline void g2x_Normalize(G2Xvector* V) {
  double n = sqrt(V->x * V->x + V->y * V->y);
  if (n > 0.) {
    V->x /= n;
    V->y /= n;
  }
}

#endif
