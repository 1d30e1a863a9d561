-- watch.s: two transputers compute while a high-priority process on each waits in an ALT on the
-- link from the other, as the workers of INMOS's ray tracer do; then P0 sends P1 a byte, P1
-- answers, and P0's ALT ends the program with SP.EXIT and status 7. Topology: configs/topologies/
-- pair.toml (host on P0.link0, P0.link1 -> P1.link0); P0 boots P1 with a copy of itself.
--
--   t800sim asm examples/iss/watch.s -o watch.btl
--   t800sim boot watch.btl --network configs/topologies/pair.toml; echo $?    # 7
--
-- Nothing a neighbour starts can be seen before its first byte arrives, one data packet later, so
-- each core runs that far ahead between synchronisations (docs/iss.md, "Time").

iterations = 20000
link0.out = #80000000
link1.out = #80000004
link0.in  = #80000010
link1.in  = #80000014
start:  ajw 64
        ldc first - f1
        ldpi
f1:     ldnl 0
        cj second
        ldc 0                  -- P0: boot P1 on link 1 with a copy that is not the first
        ldc first - f2
        ldpi
f2:     stnl 0
        ldc end - start
        stl 0
        ldlp 0
        ldc link1.out
        ldc 1
        out
        ldc start - s1
        ldpi
s1:     ldc link1.out
        ldc end - start
        out
        ldc link1.in           -- its watcher: the link from P1, and no answer to give
        stl 33
        ldc 0
        stl 34
        call spawn
        call count
        ldlp 2                 -- the byte that ends P1's wait
        ldc link1.out
        ldc 1
        out
        stopp
second: ldc link0.in           -- P1's watcher: the link from P0, answered on the same link
        stl 33
        ldc link0.out
        stl 34
        call spawn
        call count
        stopp
-- spawn: the watcher at high priority, its workspace 32 words up (its ws[1], ws[2] set above).
spawn:  ldc watch - w1
        ldpi
w1:     stl 35                 -- the caller's ws[31] is Iptr below the new workspace (4 pushed)
        ldlp 36
        runp
        ret
count:  ldc iterations
        stl 1
loop:   ldl 1
        adc -1
        stl 1
        ldl 1
        cj looped
        j loop
looped: ret
watch:  alt
        ldl 1
        ldc 1
        enbc
        altwt
        ldl 1
        ldc 1
        ldc 0
        disc
        altend
        ldlp 3
        ldl 1
        ldc 1
        in
        ldl 2
        cj exit
        ldlp 3
        ldl 2
        ldc 1
        out
        stopp
exit:   ldc #07230006          -- SP.EXIT with status 7: length 6, tag 35, INT32, pad
        stl 4
        ldc 0
        stl 5
        ldlp 4
        ldc link0.out
        ldc 8
        out
        ldlp 6
        ldc link0.in
        ldc 2
        in
        ldlp 7
        ldc link0.in
        ldl 6
        in
        stopp
        .align 4
first:  .word 1
end:
