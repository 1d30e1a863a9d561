-- output "hi" on link 0, then stop
        ajw 16
        ldc msg - here
        ldpi
here:   ldc #80000000
        ldc 2
        out
        stopp
msg:    .ascii "hi"
