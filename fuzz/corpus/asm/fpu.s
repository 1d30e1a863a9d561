        fpldzerosn
        fpuabs
        fpusqrtfirst
        fpentry
        ldc 'a' + '\n'
        nfix 1
        ldc 5 - -3
        call 0
        cj done
done:   .equ twelve, 12
        ldc twelve * . - done
