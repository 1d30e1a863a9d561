count = 5
start:  ajw 16
        ldc 0
        stl 2
        ldc count
        stl 3
top:    ldlp 2
        ldc after - top
        lend
after:  j start + 0
        .align 4
        .word #12345678, -1, 'A'
        .byte 1, 2, 3
        .space 3, #FF
