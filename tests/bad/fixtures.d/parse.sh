# Point tables for tests/bad/points_hostile.cases: one table of 2D data
# (points inside f2.exr's 64 x 64 samples) with its columns in order, and the
# same table with permuted columns, CRLF line ends and a byte order mark.
printf 'x\ty\tvalue\n3.25\t41.5\t0.75\n17.125\t8.5\t-1.25\n52.75\t30.25\t2.5\n40.5\t60.125\t0.125\n9.5\t22.75\t-0.5\n' >pxy.tsv
printf 'y\tx\tvalue\n41.5\t3.25\t0.75\n8.5\t17.125\t-1.25\n30.25\t52.75\t2.5\n60.125\t40.5\t0.125\n22.75\t9.5\t-0.5\n' >pyx.tsv
printf '\357\273\277value\ty\tx\r\n0.75\t41.5\t3.25\r\n\r\n-1.25\t8.5\t17.125\r\n2.5\t30.25\t52.75\r\n0.125\t60.125\t40.5\r\n-0.5\t22.75\t9.5\r\n' >pvyx.tsv
