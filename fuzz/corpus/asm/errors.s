        ldc undefined.name
        j 1 +
bad:    .align 3
        ldc (1 + 2 * 3
        opr #17C
bad:
