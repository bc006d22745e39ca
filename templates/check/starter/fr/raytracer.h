/* raytracer.h : les fonctions du TD 1 (RayTracer 1.0, utilitaires), avec les prototypes que le
 * cours leur donne. raytracer.c dit ce que chacune doit renvoyer (son contrat). */
#ifndef EPURE_RAYTRACER_H
#define EPURE_RAYTRACER_H

#include "g2x.h"
#include "g3x.h"

/* Exercice 1 */
G2Xpoint Projection(G2Xpoint A, G2Xpoint B, G2Xpoint C);
/* Exercice 2 */
bool InterSegments(G2Xpoint A, G2Xpoint B, G2Xpoint C, G2Xpoint D, G2Xpoint* I);
/* Exercice 3 */
bool rayon_inter_cercle(G2Xpoint* J, G2Xvector* N, G2Xpoint A, G2Xvector u, G2Xpoint C, double r);
bool rayon_inter_cercle_canonique(G2Xpoint* J, G2Xvector* N, G2Xpoint A, G2Xvector u);
/* Exercice 4 */
bool rayon_inter_carre_canonique(G2Xpoint* J, G2Xvector* N, G2Xpoint A, G2Xvector u);
/* Les questions ouvertes : une ellipse, un rectangle quelconques (par les transformations) */
bool rayon_inter_ellipse(G2Xpoint* J, G2Xvector* N, G2Xpoint A, G2Xvector u, G2Xpoint C, double a, double b,
                         double angle_deg);
bool rayon_inter_rectangle(G2Xpoint* J, G2Xvector* N, G2Xpoint A, G2Xvector u, G2Xpoint C, double w, double h,
                           double angle_deg);
/* Dans l'espace */
bool rayon_inter_sphere(G3Xpoint* J, G3Xvector* N, G3Xpoint A, G3Xvector u, G3Xpoint C, double r);
bool rayon_inter_cube_canonique(G3Xpoint* J, G3Xvector* N, G3Xpoint A, G3Xvector u);

/* A_ECRIRE(ses paramètres) : le corps d'une fonction pas encore écrite. `epure check` la signale alors comme
 * non écrite (plutôt que fausse) ; lancé seul, le programme s'arrête et dit laquelle. */
#ifdef EPURE_CHECK
_Noreturn void epure_todo(const char* function, ...);
#else
#include <stdio.h>
#include <stdlib.h>
static inline _Noreturn void epure_todo(const char* function, ...) {
  fprintf(stderr, "%s : pas encore écrite\n", function);
  abort();
}
#endif
#define A_ECRIRE(...) epure_todo(__func__, __VA_ARGS__)
#define TO_WRITE(...) epure_todo(__func__, __VA_ARGS__)

#endif
