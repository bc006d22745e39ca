/* RayTracer 1.0: utilities (tutorial 1)
 *
 * sheet: XXXX-XXXX-XXXX     <- the id printed at the top of your worksheet
 * student: First Last       <- your name
 *
 * Write each function below in place of TO_WRITE(...). Leave TO_WRITE(...) in the ones you do not
 * write: they are reported as not written. Compile on your own with
 *     gcc -std=c11 -Wall -Wextra -c raytracer.c
 * and hand in this one file. Include nothing but "raytracer.h" (or g2x.h, g3x.h) and the C
 * standard headers (<math.h>, <stdio.h>, ...). A main() of your own may stay in the file: it is
 * left out when the file is checked.
 */
#include "raytracer.h"

/* Exercise 1. The orthogonal projection P of the point C on the line (AB), with the dot product
 * alone: AP = t.AB with t = AB.AC / AB.AB.
 * A and B are distinct (the line exists). */
G2Xpoint Projection(G2Xpoint A, G2Xpoint B, G2Xpoint C) {
  TO_WRITE(A, B, C);
}

/* Exercise 2. The intersection of the segments [AB] and [CD], with 2D cross products.
 * Returns true, with *I the intersection point, when the segments cross or touch (an end of
 * one on the other counts: both parameters in [0, 1], ends included).
 * Returns false when they do not meet, and when they are parallel or collinear: AB^CD is 0 to
 * within the rounding of the data. Test it with G2Xiszero, never with == 0.
 * *I is read only when the function returns true. */
bool InterSegments(G2Xpoint A, G2Xpoint B, G2Xpoint C, G2Xpoint D, G2Xpoint* I) {
  TO_WRITE(A, B, C, D, I);
}

/* Exercise 3. The ray [A, u) (u of length 1) and the circle of centre C and radius r > 0.
 * Returns true when the ray meets the circle, with *J the first point met (the nearest to A on
 * the ray, t >= 0) and *N the unit normal to the circle at J, pointing out of the circle.
 * - A tangent ray meets the circle (at one point).
 * - A outside, the ray pointing away from the circle (t = u.AC < 0) or passing beside it: false.
 * - A on the circle, the ray entering it or along its tangent: J = A (t = 0).
 * - A inside the circle: the ray leaves it; J is where it leaves, N still points outward.
 *   (The course's code reports a miss here: it is not a miss.) */
bool rayon_inter_cercle(G2Xpoint* J, G2Xvector* N, G2Xpoint A, G2Xvector u, G2Xpoint C, double r) {
  TO_WRITE(J, N, A, u, C, r);
}

/* Exercise 3. The same with THE canonical circle: centre O, radius 1. */
bool rayon_inter_cercle_canonique(G2Xpoint* J, G2Xvector* N, G2Xpoint A, G2Xvector u) {
  TO_WRITE(J, N, A, u);
}

/* Exercise 4. The ray [A, u) (u of length 1) and THE canonical square [-1, 1] x [-1, 1].
 * Returns true when the ray meets the square, with *J the first point met and *N the outward
 * unit normal of the side at J: (+1, 0), (0, +1), (-1, 0) or (0, -1). At a corner, either
 * side's normal is right.
 * - A on a side (x_A = 1, for instance) is outside: the ray entering through that side meets it
 *   at J = A (t = 0); a ray running along a side does not enter through it.
 * - A inside the square: the ray leaves it; J is where it leaves, N points outward. */
bool rayon_inter_carre_canonique(G2Xpoint* J, G2Xvector* N, G2Xpoint A, G2Xvector u) {
  TO_WRITE(J, N, A, u);
}

/* Exercise 3, question 3. The ray [A, u) and the ellipse of centre C, semi-axes a > 0 and b > 0,
 * its a-axis turned by angle_deg degrees (counter-clockwise) from the x-axis. u is not zero,
 * and need NOT be of length 1 (a ray carried into the ellipse's own frame is not).
 * Returns what rayon_inter_cercle returns: *J the first point met, *N the outward unit normal
 * to the ellipse at J (the same cases: tangent, A on the ellipse, A inside). */
bool rayon_inter_ellipse(G2Xpoint* J, G2Xvector* N, G2Xpoint A, G2Xvector u, G2Xpoint C, double a, double b,
                         double angle_deg) {
  TO_WRITE(J, N, A, u, C, a, b, angle_deg);
}

/* Exercise 4, question 3. The ray [A, u) and the rectangle of centre C, half-sizes w > 0 and
 * h > 0 (w along the axis turned by angle_deg degrees from the x-axis). u is not zero, and need
 * not be of length 1. Returns what rayon_inter_carre_canonique returns, for this rectangle. */
bool rayon_inter_rectangle(G2Xpoint* J, G2Xvector* N, G2Xpoint A, G2Xvector u, G2Xpoint C, double w, double h,
                           double angle_deg) {
  TO_WRITE(J, N, A, u, C, w, h, angle_deg);
}

/* In space. The ray [A, u) (u of length 1) and the sphere of centre C and radius r > 0: as
 * rayon_inter_cercle, in 3D. */
bool rayon_inter_sphere(G3Xpoint* J, G3Xvector* N, G3Xpoint A, G3Xvector u, G3Xpoint C, double r) {
  TO_WRITE(J, N, A, u, C, r);
}

/* In space. The ray [A, u) (u of length 1) and THE canonical cube [-1, 1]^3: as
 * rayon_inter_carre_canonique, with six faces (on an edge or a corner, any of its faces' normals
 * is right). */
bool rayon_inter_cube_canonique(G3Xpoint* J, G3Xvector* N, G3Xpoint A, G3Xvector u) {
  TO_WRITE(J, N, A, u);
}
