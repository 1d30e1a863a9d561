-- pingpong.s: link timing seen by a program. Two transputers (configs/topologies/pair.toml: host
-- on P0.link0, P0.link1 -> P1.link0) run this code. P0 boots P1 with a copy of it, then a
-- high-priority process on P0 (its clock ticks every microsecond) sends `bytes` bytes to P1 and
-- takes them back, `rounds` times, and ends the program with SP.EXIT and the elapsed microseconds
-- as the status (the command's exit code is that modulo 256; `--json` reports it whole).
--
--   t800sim asm examples/iss/pingpong.s -o pingpong.btl
--   t800sim boot pingpong.btl --network configs/topologies/pair.toml --json report.json

link0.out = #80000000
link1.out = #80000004
link0.in  = #80000010
link1.in  = #80000014
bytes = 1000
rounds = 20

start:  ajw 40                 -- the workspace above the code
        ldc 0                  -- start the clocks, as a secondary loader does
        sttimer
        ldc first - f1
        ldpi
f1:     ldnl 0
        cj echo
        ldc 0                  -- boot P1 on link 1 with a copy that is not the first
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
        ldc timed - t1         -- the timing process: Iptr below its workspace, ws[32] on
        ldpi
t1:     stl 31
        ldlp 32                -- Wdesc with the priority bit clear: high priority
        runp
        stopp

-- At high priority. The buffer lies 512 bytes above the code, clear of both workspaces.
timed:  ldtimer
        stl 0
        ldc rounds
        stl 1
ploop:  ldc end - b1
        ldpi
b1:     adc 512
        ldc link1.out
        ldc bytes
        out
        ldc end - b2
        ldpi
b2:     adc 512
        ldc link1.in
        ldc bytes
        in
        ldl 1
        adc -1
        stl 1
        ldl 1
        cj done
        j ploop
done:   ldtimer
        ldl 0
        diff                   -- elapsed ticks of 1 us
        stl 2
        ldl 2                  -- SP.EXIT, status = the ticks: length 6, tag 35, INT32, pad
        ldc 24
        shl
        ldc #230006
        or
        stl 3
        ldl 2
        ldc 8
        shr
        stl 4
        ldlp 3
        ldc link0.out
        ldc 8
        out
        ldc 0
        stl 5
        ldlp 5
        ldc link0.in
        ldc 2
        in
        ldlp 6
        ldc link0.in
        ldl 5
        in
        stopp

echo:   ldc rounds
        stl 1
eloop:  ldc end - b3
        ldpi
b3:     adc 512
        ldc link0.in
        ldc bytes
        in
        ldc end - b4
        ldpi
b4:     adc 512
        ldc link0.out
        ldc bytes
        out
        ldl 1
        adc -1
        stl 1
        ldl 1
        cj edone
        j eloop
edone:  stopp

        .align 4
first:  .word 1
end:
