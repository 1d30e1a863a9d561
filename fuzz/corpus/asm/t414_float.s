; REAL32 1.0 * 1.0 the T414 way
        ajw 16
        ldc #3F800000
        unpacksn
        stl 1
        stl 2
        ldc 254
        stl 0
        ldc 0
        ldl 1
        ldl 1
        lmul
        norm
        postnormsn
        roundsn
        cflerr
        stopp
