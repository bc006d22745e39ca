/* raytracer.h: the functions of tutorial 1 (RayTracer 1.0, utilities), with the prototypes the
 * course gives them. raytracer.c says what each must return (its contract). */
#ifndef EPURE_RAYTRACER_H
#define EPURE_RAYTRACER_H

#include "g2x.h"
#include "g3x.h"

/* Exercise 1 */
G2Xpoint Projection(G2Xpoint A, G2Xpoint B, G2Xpoint C);
/* Exercise 2 */
bool InterSegments(G2Xpoint A, G2Xpoint B, G2Xpoint C, G2Xpoint D, G2Xpoint* I);
/* Exercise 3 */
bool rayon_inter_cercle(G2Xpoint* J, G2Xvector* N, G2Xpoint A, G2Xvector u, G2Xpoint C, double r);
bool rayon_inter_cercle_canonique(G2Xpoint* J, G2Xvector* N, G2Xpoint A, G2Xvector u);
/* Exercise 4 */
bool rayon_inter_carre_canonique(G2Xpoint* J, G2Xvector* N, G2Xpoint A, G2Xvector u);
/* The open questions: any ellipse, any rectangle (through transformations) */
bool rayon_inter_ellipse(G2Xpoint* J, G2Xvector* N, G2Xpoint A, G2Xvector u, G2Xpoint C, double a, double b,
                         double angle_deg);
bool rayon_inter_rectangle(G2Xpoint* J, G2Xvector* N, G2Xpoint A, G2Xvector u, G2Xpoint C, double w, double h,
                           double angle_deg);
/* In space */
bool rayon_inter_sphere(G3Xpoint* J, G3Xvector* N, G3Xpoint A, G3Xvector u, G3Xpoint C, double r);
bool rayon_inter_cube_canonique(G3Xpoint* J, G3Xvector* N, G3Xpoint A, G3Xvector u);

/* TO_WRITE(its parameters): the body of a function not written yet. `epure check` then reports the function
 * as not written (rather than wrong); run on its own, the program stops and says which. */
#ifdef EPURE_CHECK
_Noreturn void epure_todo(const char* function, ...);
#else
#include <stdio.h>
#include <stdlib.h>
static inline _Noreturn void epure_todo(const char* function, ...) {
  fprintf(stderr, "%s: not written yet\n", function);
  abort();
}
#endif
#define TO_WRITE(...) epure_todo(__func__, __VA_ARGS__)
#define A_ECRIRE(...) epure_todo(__func__, __VA_ARGS__)

#endif
