-- echo.s: prints the program's command line, as `echo` would.
--
--   t800sim asm examples/iss/echo.s -o echo.btl
--   t800sim boot echo.btl -- hello there          # prints "hello there"
--
-- It asks the host for the short command line (SP.COMMANDLINE: the arguments after `--`), then
-- writes them to stdout with SP.WRITE and ends with SP.EXIT. The reply and the request it builds
-- live in memory above the workspace (128 and 384 bytes above the code), the rest in the
-- workspace (16 words above the code).

link0.out = #80000000
link0.in  = #80000010

-- ws[0] &reply, ws[1] the line's length, ws[2] &packet, ws[3] the packet's body length
start:  ajw 16
        ldc request - r1
        ldpi
r1:     ldc 8
        call send              -- the reply: result, INT16 length, the line
        ldc (end + 128) - a1
        ldpi
a1:     stl 0
        ldl 0
        adc 1
        lb                     -- the length's low byte: lines of up to 255 bytes
        stl 1
        ldc (end + 384) - a2
        ldpi
a2:     stl 2
        ldl 1                  -- body: tag, INT32 stream, INT16 count, the line; even length
        adc 8
        ldc -2
        and
        stl 3
        ldl 3                  -- the packet's length field, low byte (high byte 0)
        ldl 2
        sb
        ldc 13                 -- SP.WRITE
        ldl 2
        adc 2
        sb
        ldc 1                  -- stream 1 (stdout); its three high bytes are still 0
        ldl 2
        adc 3
        sb
        ldl 1                  -- the count, low byte
        ldl 2
        adc 7
        sb
        ldl 0                  -- move: C the line, B where it goes, A its length
        adc 3
        ldl 2
        adc 9
        ldl 1
        move
        ldl 2
        ldl 3
        adc 2
        call send
        ldc exit - e1
        ldpi
e1:     ldc 8
        call send
        stopp

-- send: out the packet at B of A bytes, then the reply's length into ws[0] and its body at reply.
send:   ajw -4
        ldl 6
        ldc link0.out
        ldl 5
        out
        ldc 0
        stl 0
        ldlp 0
        ldc link0.in
        ldc 2
        in
        ldc (end + 128) - s1
        ldpi
s1:     ldc link0.in
        ldl 0
        in
        ajw 4
        ret

request: .byte 6, 0, 40, 0, 0, 0, 0, 0   -- SP.COMMANDLINE, the short line
exit:    .byte 6, 0, 35
         .word 999999999                 -- SP.EXIT, sps.success
         .byte 0
         .align 4
end:
