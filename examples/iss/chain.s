-- chain.s: a network boot and a reduction along a chain of transputers (configs/topologies/
-- pipeline-6.toml, or any chain wired Pi.link1 -> P(i+1).link0 with the host on P0.link0).
--
-- Every processor runs this same code. Booted through its link 0, it first boots its neighbour on
-- link 1 with a copy of itself whose `hops` is one less (the chip's boot protocol: a length byte,
-- then the code), then counts down a loop of `iterations`, then adds the count of processors
-- behind it (input on link 1) to its own one and passes the sum back on link 0. The first
-- processor, the one the host booted, ends the program with SP.EXIT and the sum as the status,
-- so `t800sim boot` exits with the number of processors that ran: 6 on pipeline-6.
--
--   t800sim asm examples/iss/chain.s -o chain.btl
--   t800sim boot chain.btl --network configs/topologies/pipeline-6.toml; echo $?

link0.out = #80000000
link1.out = #80000004
link0.in  = #80000010
link1.in  = #80000014
iterations = 100000

-- ws[0] hops left, ws[1] first, ws[2] scratch, ws[3] loop count, ws[4] the sum from behind,
-- ws[5..6] the SP.EXIT packet, ws[7..9] its reply
start:  ajw 24                 -- the workspace above the code (its lowest words are the
                               -- scheduler's while a process waits)
        ldc hops - h1
        ldpi
h1:     ldnl 0
        stl 0
        ldc first - f1
        ldpi
f1:     ldnl 0
        stl 1
        ldl 0
        cj compute             -- the last of the chain boots nobody
        ldl 0                  -- the copy: one hop less, not the first
        adc -1
        ldc hops - h2
        ldpi
h2:     stnl 0
        ldc 0
        ldc first - f2
        ldpi
f2:     stnl 0
        ldc end - start        -- the boot protocol's length byte
        stl 2
        ldlp 2
        ldc link1.out
        ldc 1
        out
        ldc start - s1         -- then the code itself
        ldpi
s1:     ldc link1.out
        ldc end - start
        out

compute:
        ldc iterations
        stl 3
loop:   ldl 3
        adc -1
        stl 3
        ldl 3
        cj counted
        j loop

counted:
        ldc 0
        stl 4
        ldl 0
        cj reply
        ldlp 4                 -- how many ran behind us
        ldc link1.in
        ldc 4
        in
reply:  ldl 4
        adc 1
        stl 4
        ldl 1
        cj pass.back
        ldl 4                  -- first: SP.EXIT, status = the sum. Body: tag 35, INT32, a pad
        ldc 24
        shl
        ldc #230006            -- length 6 (2 bytes), tag 35, then the status's low byte
        or
        stl 5
        ldl 4
        ldc 8
        shr
        stl 6
        ldlp 5
        ldc link0.out
        ldc 8
        out
        ldc 0
        stl 7
        ldlp 7                 -- the reply: its length, then its body
        ldc link0.in
        ldc 2
        in
        ldlp 8
        ldc link0.in
        ldl 7
        in
        stopp
pass.back:
        ldlp 4
        ldc link0.out
        ldc 4
        out
        stopp

        .align 4
hops:   .word 5                -- processors after this one
first:  .word 1
end:
