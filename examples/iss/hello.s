-- hello.s: the smallest program that talks to the host. It writes "hello, transputer" to the
-- host's stdout with one SP.WRITE request and ends with SP.EXIT, as a program built with the INMOS
-- toolset's hostio library does (tags and fields: t800/host/sp_protocol.hpp).
--
--   t800sim asm examples/iss/hello.s -o hello.btl
--   t800sim boot hello.btl
--
-- An SP request is a packet on the host link (link 0 here): a 2-byte little-endian length, then
-- the body, tag first, padded to an even length of at least 6. Every request gets a reply packet.

link0.out = #80000000
link0.in  = #80000010

start:  ajw 16                 -- workspace above the code: a process descheduled keeps its
                               -- Iptr and queue link in the words just below Wptr, which
                               -- must not be code or data
        ldc write - w1         -- SP.WRITE "hello, transputer\n" to stream 1 (stdout)
        ldpi
w1:     ldc write.end - write
        call send
        ldc exit - e1          -- SP.EXIT with the toolset's sps.success
        ldpi
e1:     ldc exit.end - exit
        call send
        stopp                  -- the host has stopped serving

-- send: out the packet at B of A bytes, then take the reply's length and body into the workspace.
-- call pushed Iptr, A, B, C into the four words at the new Wptr: ws[1] = count, ws[2] = pointer.
send:   ajw -4                 -- four words of our own below
        ldl 6                  -- the packet
        ldc link0.out
        ldl 5                  -- its length
        out
        ldc 0
        stl 0
        ldlp 0                 -- the reply's length, 2 bytes, into ws[0]
        ldc link0.in
        ldc 2
        in
        ldlp 1                 -- its body (at most 8 bytes for these replies) into ws[1], ws[2]
        ldc link0.in
        ldl 0
        in
        ajw 4
        ret

write:  .byte 26, 0            -- body length: tag, stream, count, 18 bytes of text, 1 pad
        .byte 13               -- SP.WRITE
        .word 1                -- stream 1: stdout
        .byte 18, 0            -- 18 bytes
        .ascii "hello, transputer\n"
        .byte 0                -- the body's pad to an even length
write.end:
        .align 4
exit:   .byte 6, 0
        .byte 35               -- SP.EXIT
        .word 999999999        -- sps.success: the iserver exits 0
        .byte 0
exit.end:
