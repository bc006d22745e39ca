/* RayTracer 1.0 : utilitaires (TD 1)
 *
 * feuille : XXXX-XXXX-XXXX     <- l'identifiant imprimé en haut de ta feuille
 * étudiant : Prénom Nom        <- ton nom
 *
 * Écris chaque fonction ci-dessous à la place de A_ECRIRE(...). Laisse A_ECRIRE(...) dans celles que tu
 * n'écris pas : elles sont signalées comme non écrites. Compile seul avec
 *     gcc -std=c11 -Wall -Wextra -c raytracer.c
 * et rends ce seul fichier. N'inclus rien d'autre que "raytracer.h" (ou g2x.h, g3x.h) et les
 * en-têtes standard du C (<math.h>, <stdio.h>, ...). Un main() à toi peut rester dans le
 * fichier : il est mis de côté quand le fichier est vérifié.
 */
#include "raytracer.h"

/* Exercice 1. La projection orthogonale P du point C sur la droite (AB), par le seul produit
 * scalaire : AP = t.AB avec t = AB.AC / AB.AB.
 * A et B sont distincts (la droite existe). */
G2Xpoint Projection(G2Xpoint A, G2Xpoint B, G2Xpoint C) {
  A_ECRIRE(A, B, C);
}

/* Exercice 2. L'intersection des segments [AB] et [CD], par les produits vectoriels 2D.
 * Renvoie true, avec *I le point d'intersection, quand les segments se coupent ou se touchent
 * (une extrémité de l'un sur l'autre compte : les deux paramètres dans [0, 1], bornes comprises).
 * Renvoie false quand ils ne se rencontrent pas, et quand ils sont parallèles ou alignés : AB^CD
 * est nul aux arrondis des données près. Teste-le avec G2Xiszero, jamais avec == 0.
 * *I n'est lu que si la fonction renvoie true. */
bool InterSegments(G2Xpoint A, G2Xpoint B, G2Xpoint C, G2Xpoint D, G2Xpoint* I) {
  A_ECRIRE(A, B, C, D, I);
}

/* Exercice 3. Le rayon [A, u) (u normé) et le cercle de centre C et de rayon r > 0.
 * Renvoie true quand le rayon rencontre le cercle, avec *J le premier point rencontré (le plus
 * proche de A sur le rayon, t >= 0) et *N la normale unitaire au cercle en J, sortante.
 * - Un rayon tangent rencontre le cercle (en un point).
 * - A dehors, le rayon qui s'éloigne du cercle (t = u.AC < 0) ou qui passe à côté : false.
 * - A sur le cercle, le rayon qui y entre ou qui suit sa tangente : J = A (t = 0).
 * - A dans le cercle : le rayon en sort ; J est le point de sortie, N reste sortante.
 *   (Le code du cours répond « pas d'intersection » ici : ce n'en est pas une.) */
bool rayon_inter_cercle(G2Xpoint* J, G2Xvector* N, G2Xpoint A, G2Xvector u, G2Xpoint C, double r) {
  A_ECRIRE(J, N, A, u, C, r);
}

/* Exercice 3. La même chose avec LE cercle canonique : centre O, rayon 1. */
bool rayon_inter_cercle_canonique(G2Xpoint* J, G2Xvector* N, G2Xpoint A, G2Xvector u) {
  A_ECRIRE(J, N, A, u);
}

/* Exercice 4. Le rayon [A, u) (u normé) et LE carré canonique [-1, 1] x [-1, 1].
 * Renvoie true quand le rayon rencontre le carré, avec *J le premier point rencontré et *N la
 * normale unitaire sortante du côté en J : (+1, 0), (0, +1), (-1, 0) ou (0, -1). Sur un coin, la
 * normale de l'un ou l'autre côté est juste.
 * - A sur un côté (x_A = 1 par exemple) est dehors : le rayon qui entre par ce côté le rencontre
 *   en J = A (t = 0) ; un rayon qui longe un côté n'entre pas par lui.
 * - A dans le carré : le rayon en sort ; J est le point de sortie, N est sortante. */
bool rayon_inter_carre_canonique(G2Xpoint* J, G2Xvector* N, G2Xpoint A, G2Xvector u) {
  A_ECRIRE(J, N, A, u);
}

/* Exercice 3, question 3. Le rayon [A, u) et l'ellipse de centre C, de demi-axes a > 0 et b > 0,
 * son axe a tourné de angle_deg degrés (sens direct) depuis l'axe des x. u n'est pas nul, et PAS
 * forcément normé (un rayon porté dans le repère propre de l'ellipse ne l'est pas).
 * Renvoie ce que renvoie rayon_inter_cercle : *J le premier point rencontré, *N la normale
 * unitaire sortante à l'ellipse en J (mêmes cas : tangent, A sur l'ellipse, A dedans). */
bool rayon_inter_ellipse(G2Xpoint* J, G2Xvector* N, G2Xpoint A, G2Xvector u, G2Xpoint C, double a, double b,
                         double angle_deg) {
  A_ECRIRE(J, N, A, u, C, a, b, angle_deg);
}

/* Exercice 4, question 3. Le rayon [A, u) et le rectangle de centre C, de demi-côtés w > 0 et
 * h > 0 (w le long de l'axe tourné de angle_deg degrés depuis l'axe des x). u n'est pas nul, et
 * pas forcément normé. Renvoie ce que renvoie rayon_inter_carre_canonique, pour ce rectangle. */
bool rayon_inter_rectangle(G2Xpoint* J, G2Xvector* N, G2Xpoint A, G2Xvector u, G2Xpoint C, double w, double h,
                           double angle_deg) {
  A_ECRIRE(J, N, A, u, C, w, h, angle_deg);
}

/* Dans l'espace. Le rayon [A, u) (u normé) et la sphère de centre C et de rayon r > 0 : comme
 * rayon_inter_cercle, en 3D. */
bool rayon_inter_sphere(G3Xpoint* J, G3Xvector* N, G3Xpoint A, G3Xvector u, G3Xpoint C, double r) {
  A_ECRIRE(J, N, A, u, C, r);
}

/* Dans l'espace. Le rayon [A, u) (u normé) et LE cube canonique [-1, 1]^3 : comme
 * rayon_inter_carre_canonique, avec six faces (sur une arête ou un coin, la normale de l'une ou
 * l'autre de ses faces est juste). */
bool rayon_inter_cube_canonique(G3Xpoint* J, G3Xvector* N, G3Xpoint A, G3Xvector u) {
  A_ECRIRE(J, N, A, u);
}
