/* sheet: 1000-0005-002N
 * student: Zoé Lefèvre */
