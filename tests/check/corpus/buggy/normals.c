/* Normals: not normalised (circle, sphere), pointing inward (square, cube), the ellipse's carried like a vector.
 * student: Noé N. */
#include <float.h>
#include "raytracer.h"

G2Xpoint Projection(G2Xpoint A, G2Xpoint B, G2Xpoint C)
{
   G2Xvector AB = g2x_SetVect(A,B);
   G2Xvector AC = g2x_SetVect(A,C);
   double   t = g2x_ProdScal(AB,AC)/g2x_ProdScal(AB,AB);
   return (G2Xpoint){A.x+t*AB.x,A.y+t*AB.y};
}

bool InterSegments(G2Xpoint A, G2Xpoint B, G2Xpoint C, G2Xpoint D, G2Xpoint *I)
{
  G2Xvector AB = g2x_SetVect(A,B);
  G2Xvector CD = g2x_SetVect(C,D);
  double    v = g2x_ProdVect(AB,CD);
  if (G2Xiszero(v)) return false;       /* si les 2 droites sont parallèles, on arrête */
  G2Xvector AC=g2x_SetVect(A,C);
  double t1 = g2x_ProdVect(AC,CD)/v;    /* t1 : position de I sur la droite (AB) */
  if (t1<0. || t1 >1.) return false;    /* si I n'appartient pas à [A,B] inutile de continuer */
  double t2 = g2x_ProdVect(AC,AB)/v;    /* t2 : position de I sur la droite (CD) */
  if (t2<0. || t2 >1.) return false;    /* si I n'appartient pas à [C,D] inutile de continuer */
  I->x = A.x+t1*AB.x;                   /* si on est arrivé là, on a le point I */
  I->y = A.y+t1*AB.y;
  return true;
}

/* Intersection d'un rayon avec un cercle quelconque */
bool rayon_inter_cercle(G2Xpoint* J, G2Xvector* N, G2Xpoint A, G2Xvector u, G2Xpoint C, double r)
{
  G2Xvector AC = g2x_SetVect(A,C);
  double    t = g2x_ProdScal(u,AC);
  bool inside = g2x_ProdScal(AC,AC) < r*r;   /* A dans le cercle : le rayon en sort */
  if (!inside && t<0.) return false;   /* le rayon ne se dirige pas vers le cercle */
  double d2 = g2x_ProdVect(u,AC);      /* d donne la distance de C à sa proj. P */
         d2 = SQR(d2);
  if (d2>r*r) return false;            /* le rayon passe à côté du cercle */
  t = inside ? t+sqrt(r*r-d2) : t-sqrt(r*r-d2);
  J->x = A.x + t*u.x;                  /* si on est arrivé là, on a le point J */
  J->y = A.y + t*u.y;
  *N = g2x_SetVect(C,*J);              /* et la normale en J */
  return true;
}

/* Intersection d'un rayon avec LE cercle canonique */
bool rayon_inter_cercle_canonique(G2Xpoint* J, G2Xvector* N, G2Xpoint A, G2Xvector u)
{
  /* les coord. de A sont celle du vecteur OA = -AO => inversion de signe */
  double t = -g2x_ProdScal(u,(G2Xvector)A);
  bool inside = g2x_ProdScal((G2Xvector)A,(G2Xvector)A) < 1.;
  if (!inside && t<0.) return false;   /* le rayon ne se dirige pas vers le cercle */
  double d2 = g2x_ProdVect(u,(G2Xvector)A);
         d2 = SQR(d2);                 /* d donne la distance de C à sa proj. P */
  if (d2>1) return false;              /* le rayon passe à côté du cercle */
  t = inside ? t+sqrt(1.-d2) : t-sqrt(1.-d2);
  J->x = A.x + t*u.x;                  /* si on est arrivé là, on a le point J */
  J->y = A.y + t*u.y;
  *N = (G2Xvector)(*J);                /* et la normale en J (déjà normée) */
  return true;
}

/* Intersection d'un rayon avec LE carré canonique (même prototype que le pour le cercle) */
bool rayon_inter_carre_canonique(G2Xpoint* J, G2Xvector* N, G2Xpoint A, G2Xvector u)
{
  bool flag[4]={false,false,false,false}; /* flags de positionnement de la source du rayon par rapport aux 4 faces */
  static G2Xcoord CN[4]={{+1.,0.},{0.,+1.},{-1.,0.},{0.,-1.}}; /* les 4 centres de face et normales exterieures */
  flag[0]=(bool)(A.x>=+1.); /* au max. 2 valeurs vraies sur les 4 (0 si A est dans le carré) */
  flag[1]=(bool)(A.y>=+1.);
  flag[2]=(bool)(A.x<=-1.);
  flag[3]=(bool)(A.y<=-1.);
  int i;
  if (!flag[0] && !flag[1] && !flag[2] && !flag[3])
  { /* A dans le carré : le rayon sort par le premier côté qu'il rencontre */
    double tmin = DBL_MAX; int imin = -1;
    for (i=0;i<4;i++)
    {
      double ps2 = g2x_ProdScal(u,CN[i]); if (ps2<=0.) continue;
      double t = (1.-g2x_ProdScal((G2Xvector)A,CN[i]))/ps2;
      if (t<tmin) { tmin=t; imin=i; }
    }
    J->x = A.x+tmin*u.x;
    J->y = A.y+tmin*u.y;
    N->x=-CN[imin].x; N->y=-CN[imin].y;
    return true;
  }
  for (i=0;i<4;i++)
  { /* on ne traite que les faces "visibles" depuis [A,u) */
    if (flag[i]==false) continue;
    double ps1 = g2x_ProdScal(g2x_SetVect(A,CN[i]),CN[i]); if (ps1>0.) continue;
    double ps2 = g2x_ProdScal(u                   ,CN[i]); if (ps2>=0.) continue;
    double t=ps1/ps2;
    J->x = A.x+t*u.x;
    J->y = A.y+t*u.y;
    /* si J n'est pas sur le côté, ce n'est pas le bon, on continue (la coordonnée le long du côté) */
    if (fabs(i%2==0 ? J->y : J->x)>1.) continue;
    N->x=-CN[i].x; N->y=-CN[i].y;         /* sinon, on récupère la normale courante et on s'en va */
    return true;
  }
  return false;
}

/* L'ellipse : le rayon porté dans le repère propre (translation, rotation, échelle), puis le cercle
 * canonique avec la direction portée normée, et le point et la normale ramenés. */
bool rayon_inter_ellipse(G2Xpoint* J, G2Xvector* N, G2Xpoint A, G2Xvector u, G2Xpoint C, double a, double b,
                         double angle_deg)
{
  double al = angle_deg*3.14159265358979323846/180., co = cos(al), si = sin(al);
  G2Xvector d = g2x_SetVect(C,A);
  G2Xpoint  Ac = {( co*d.x+si*d.y)/a, (-si*d.x+co*d.y)/b};
  G2Xvector uc = {( co*u.x+si*u.y)/a, (-si*u.x+co*u.y)/b};
  g2x_Normalize(&uc);
  G2Xpoint Jc; G2Xvector Nc;
  if (!rayon_inter_cercle_canonique(&Jc,&Nc,Ac,uc)) return false;
  J->x = C.x + co*a*Jc.x - si*b*Jc.y;
  J->y = C.y + si*a*Jc.x + co*b*Jc.y;
  N->x = co*Nc.x*a - si*Nc.y*b;          /* carried like a vector */
  N->y = si*Nc.x*a + co*Nc.y*b;
  g2x_Normalize(N);
  return true;
}

bool rayon_inter_rectangle(G2Xpoint* J, G2Xvector* N, G2Xpoint A, G2Xvector u, G2Xpoint C, double w, double h,
                           double angle_deg)
{
  double al = angle_deg*3.14159265358979323846/180., co = cos(al), si = sin(al);
  G2Xvector d = g2x_SetVect(C,A);
  G2Xpoint  Ac = {( co*d.x+si*d.y)/w, (-si*d.x+co*d.y)/h};
  G2Xvector uc = {( co*u.x+si*u.y)/w, (-si*u.x+co*u.y)/h};
  G2Xpoint Jc; G2Xvector Nc;
  if (!rayon_inter_carre_canonique(&Jc,&Nc,Ac,uc)) return false;  /* t a le même sens : pas besoin de normer */
  J->x = C.x + co*w*Jc.x - si*h*Jc.y;
  J->y = C.y + si*w*Jc.x + co*h*Jc.y;
  N->x = co*Nc.x - si*Nc.y;
  N->y = si*Nc.x + co*Nc.y;
  return true;
}

bool rayon_inter_sphere(G3Xpoint* J, G3Xvector* N, G3Xpoint A, G3Xvector u, G3Xpoint C, double r)
{
  G3Xvector AC = g3x_SetVect(A,C);
  double    t = g3x_ProdScal(u,AC);
  bool inside = g3x_ProdScal(AC,AC) < r*r;
  if (!inside && t<0.) return false;
  G3Xvector w = g3x_ProdVect(u,AC);
  double d2 = g3x_ProdScal(w,w);
  if (d2>r*r) return false;
  t = inside ? t+sqrt(r*r-d2) : t-sqrt(r*r-d2);
  *J = (G3Xpoint){A.x+t*u.x, A.y+t*u.y, A.z+t*u.z};
  *N = g3x_SetVect(C,*J);
  return true;
}

bool rayon_inter_cube_canonique(G3Xpoint* J, G3Xvector* N, G3Xpoint A, G3Xvector u)
{
  double a[3] = {A.x,A.y,A.z}, v[3] = {u.x,u.y,u.z};
  int k, s;
  bool outside = false;
  for (k=0;k<3;k++) if (fabs(a[k])>=1.) outside = true;
  if (!outside)
  { /* A dans le cube : la face de sortie */
    double tmin = DBL_MAX; int kmin = 0; double smin = 1.;
    for (k=0;k<3;k++) for (s=-1;s<=1;s+=2)
    {
      double ps2 = s*v[k]; if (ps2<=0.) continue;
      double t = (1.-s*a[k])/ps2;
      if (t<tmin) { tmin=t; kmin=k; smin=s; }
    }
    *J = (G3Xpoint){A.x+tmin*u.x, A.y+tmin*u.y, A.z+tmin*u.z};
    *N = (G3Xvector){kmin==0?-smin:0., kmin==1?-smin:0., kmin==2?-smin:0.};
    return true;
  }
  for (k=0;k<3;k++) for (s=1;s>=-1;s-=2)
  {
    if (s*a[k]<1.) continue;               /* face non candidate */
    double ps2 = s*v[k]; if (ps2>=0.) continue;
    double t = (1.-s*a[k])/ps2;
    double j[3] = {a[0]+t*v[0], a[1]+t*v[1], a[2]+t*v[2]};
    if (fabs(j[(k+1)%3])>1. || fabs(j[(k+2)%3])>1.) continue;
    *J = (G3Xpoint){j[0],j[1],j[2]};
    *N = (G3Xvector){k==0?-s:0., k==1?-s:0., k==2?-s:0.};
    return true;
  }
  return false;
}
