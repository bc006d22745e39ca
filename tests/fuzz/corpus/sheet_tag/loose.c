// feuille : 10000005002n
// étudiant : Léo
