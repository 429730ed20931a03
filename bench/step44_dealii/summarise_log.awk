# Summary of one deal.II step-44 log: prints "dofs,newton,cg".
# Newton iterations = rows of the convergence table that performed a linear solve
# ("  k  ... |  LIN_IT ..."); CG iterations = sum of LIN_IT (outer CG on the
# displacement/condensed system; the inner CG for K_Jp^{-1} is not printed).
# Used by run_step44.sh and step44_vs_dealii.py: awk -f summarise_log.awk step44.log
/Number of degrees of freedom:/ && dofs == "" {
  line = $0; sub(/.*Number of degrees of freedom: */, "", line); sub(/[^0-9].*/, "", line); dofs = line
}
/\|/ && $0 ~ /^ *[0-9]+ / {
  split($0, cols, "|"); split(cols[2], f, " ")
  if (f[1] ~ /^[0-9]+$/) { n++; cg += f[1] }
}
END { printf "%s,%s,%s\n", dofs, (n ? n : ""), (n ? cg : "") }
