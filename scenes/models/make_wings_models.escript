#!/usr/bin/env escript
%% Writes the Wings3D (.wings) files of the scenes and of the unit tests with Erlang's own encoder
%% (term_to_binary), in the layout Wings3D's src/wings_ff_wings.erl saves:
%%   "#!WINGS-1.0\r\n\032\04", <<Size:32>>, term_to_binary({wings, 2, {Shapes, Materials, Props}}, [compressed])
%% with each shape {object, Name, {winged, Edges, Faces, Vertices, HardEdges}, Props} in Wings'
%% winged-edge form (see scene/include/glass/scene/wings_file.h).
%%
%% Usage: escript scenes/models/make_wings_models.escript REPOSITORY_ROOT
%% Writes scenes/models/*.wings, examples/homework45/l_block.wings,
%% tests/homework45/l_block_uprights.wings, tests/homework45/l_block_all_hard.wings,
%% tests/homework45/l_block_partial*.wings, tests/homework45/overhang_*.wings,
%% tests/homework45/two_layers_uprights.wings, tests/homework45/l_on_slab.wings,
%% tests/homework45/slab_on_l.wings, tests/homework45/l_on_slab_sharp_corners.wings, tests/homework45/u_on_slab.wings, tests/homework45/ring_on_slab.wings,
%% tests/homework45/bar_on_slab.wings, tests/homework45/bar_stretches.wings, tests/homework45/ring.wings,
%% tests/homework45/l_inside_slab.wings, tests/homework45/l_inside_slab_sharp_inner.wings,
%% tests/homework45/refused_*.wings (objects the homework program refuses) and tests/unit/data/wings/*.wings and *.term.

main([Root]) ->
    Models = filename:join(Root, "scenes/models"),
    Tests = filename:join(Root, "tests/unit/data/wings"),
    ok = filelib:ensure_dir(filename:join(Tests, "x")),
    Materials = [material(wood, {0.85, 0.75, 0.6, 1.0}, 0.1),
                 material(paint, {0.75, 0.15, 0.1, 1.0}, 0.5)],
    %% The homework's object: a block of 2 x 2 x 2 cubes (so its faces are split by flat edges),
    %% its four top edges and one upright edge marked: a sphere corner, three mitres, and one
    %% marked edge that ends at a sharp corner.
    {BlockVs, BlockFs} = cubes([{X, Y, Z} || X <- [0, 1], Y <- [0, 1], Z <- [0, 1]], 0.75, {-0.75, 0.0, -0.75}),
    BlockHard = fun(A, B) -> top_ring_and_upright(A, B, 1.5, {-0.75, 0.0, -0.75}) end,
    write(filename:join(Models, "block.wings"),
          [object("Block", BlockVs, BlockFs, BlockHard, top_paint, true)], Materials, []),
    %% The homework's L: three cubes with y up, its uprights marked (the inner one concave) and
    %% the top edges along its outside: sphere corners, mitres, a concave fillet and its webs.
    {LBlockVs, LBlockFs} = cubes([{0, 0, 0}, {1, 0, 0}, {0, 0, 1}], 0.75, {-0.75, 0.0, -0.75}),
    LBlockHard = fun(A, B) -> upright(A, B) orelse outer_top(A, B, 0.75, -0.75, 0.75) end,
    write(filename:join(Models, "l_block.wings"),
          [object("L", LBlockVs, LBlockFs, LBlockHard, top_paint, true)], Materials, []),
    write(filename:join(Tests, "l_block.wings"),
          [object("L", LBlockVs, LBlockFs, LBlockHard, top_paint, true)], Materials, []),
    %% The same L with every edge marked: its inner upright's fillet meets the rounded rims of
    %% the top and the bottom in torus pieces.
    write(filename:join(Models, "l_all_hard.wings"),
          [object("L", LBlockVs, LBlockFs, fun(_, _) -> true end, top_paint, true)], Materials, []),
    %% The same with one top rim edge where the inner upright ends left sharp: the torus piece
    %% above the fillet ends in a flat cap against it.
    OneSharpRim = fun(A, B) -> lists:sort([A, B]) =/= [{0.0, 0.75, 0.0}, {0.75, 0.75, 0.0}] end,
    write(filename:join(Models, "l_one_sharp_rim.wings"),
          [object("L", LBlockVs, LBlockFs, OneSharpRim, top_paint, true)], Materials, []),
    %% The same L of unit cubes with only its uprights marked, and one two cubes tall (its
    %% concave upright runs straight through a corner of four faces).
    {LVsUp, LFsUp} = cubes([{0, 0, 0}, {1, 0, 0}, {0, 0, 1}], 1.0, {0.0, 0.0, 0.0}),
    Upright = fun(A, B) -> upright(A, B) end,
    write(filename:join(Tests, "l_uprights.wings"),
          [object("L", LVsUp, LFsUp, Upright, top_paint, true)], Materials, []),
    {LTallVs, LTallFs} = cubes([{X, Y, Z} || {X, Z} <- [{0, 0}, {1, 0}, {0, 1}], Y <- [0, 1]], 1.0, {0.0, 0.0, 0.0}),
    write(filename:join(Tests, "l_tall_uprights.wings"),
          [object("L", LTallVs, LTallFs, Upright, top_paint, true)], Materials, []),
    %% The homework program's object: the L of unit cubes centred on the origin, its uprights
    %% and every edge around its top marked (the program rounds both: sphere corners, mitres and,
    %% above the inner upright, a torus piece).
    HwCells = [{0, 0, 0}, {1, 0, 0}, {0, 0, 1}],
    {HwVs, HwFs} = cubes(HwCells, 1.0, {-1.0, 0.0, -1.0}),
    HwHard = fun(A, B) -> upright(A, B) orelse top_rim(A, B, 1.0, HwCells, 1.0, {-1.0, 0.0, -1.0}) end,
    write(filename:join(Root, "examples/homework45/l_block.wings"),
          [object("L", HwVs, HwFs, HwHard, top_paint, true)], Materials, []),
    %% The same with every edge hard: the bottom's rim is rounded too.
    All = fun(_, _) -> true end,
    write(filename:join(Root, "tests/homework45/l_block_all_hard.wings"),
          [object("L", HwVs, HwFs, All, top_paint, true)], Materials, []),
    %% The same with only its uprights hard (its test compares the two).
    write(filename:join(Root, "tests/homework45/l_block_uprights.wings"),
          [object("L", HwVs, HwFs, Upright, top_paint, true)], Materials, []),
    %% Partly marked rims: the top's along the back (z = -1) and along the inner side of the arm
    %% (x = 0, z >= 0), the bottom's along the right (x = 1) and the arm's front (z = 0, x >= 0);
    %% the uprights at x = -1 and the inner one hard. Where a rounded stretch meets a sharp one
    %% above a rounded upright the sphere or torus piece ends in a cap; above a sharp one the
    %% strip ends in the sharp side's plane.
    Partial = fun(A, B) ->
                  (upright(A, B) andalso (element(1, A) == -1.0 orelse {element(1, A), element(3, A)} == {0.0, 0.0}))
                  orelse level_side(A, B, 1.0, z, -1.0, any) orelse level_side(A, B, 1.0, x, 0.0, z)
                  orelse level_side(A, B, 0.0, x, 1.0, any) orelse level_side(A, B, 0.0, z, 0.0, x)
              end,
    write(filename:join(Root, "tests/homework45/l_block_partial.wings"),
          [object("L", HwVs, HwFs, Partial, top_paint, true)], Materials, []),
    %% The same rims with every upright sharp, the top's along the arm's end (z = 1) too: strips
    %% ending in a sharp side's plane at convex corners (cutting that side's face) and at the
    %% concave one (a quarter moon past the corner).
    PartialSharp = fun(A, B) ->
                       level_side(A, B, 1.0, z, -1.0, any) orelse level_side(A, B, 1.0, x, 0.0, z)
                       orelse level_side(A, B, 1.0, z, 1.0, any) orelse level_side(A, B, 0.0, z, 0.0, x)
                   end,
    write(filename:join(Root, "tests/homework45/l_block_partial_sharp_uprights.wings"),
          [object("L", HwVs, HwFs, PartialSharp, top_paint, true)], Materials, []),
    %% The back's top rim (two edges) hard only along x >= 0: a side hard in part, rounded along
    %% its hard stretch.
    HalfSide = fun(A, B) -> level_side(A, B, 1.0, z, -1.0, x) end,
    write(filename:join(Root, "tests/homework45/l_block_half_side.wings"),
          [object("L", HwVs, HwFs, HalfSide, top_paint, true)], Materials, []),
    %% A bar of three cubes whose rims are hard along stretches that end in the middle of its
    %% sides: the front's top (z = 0) over the middle cube only, the back's bottom (z = 1) from
    %% x = 1 on, the right end's top (x = 3) and the upright at its back: strips ending in
    %% quarter moons across the side at both ends, the top's and the bottom's changing at other
    %% places, and a sphere piece ending in a cap.
    {BarVs, BarFs} = cubes([{0, 0, 0}, {1, 0, 0}, {2, 0, 0}], 1.0, {0.0, 0.0, 0.0}),
    Within = fun({AX, _, _}, {BX, _, _}, Low, High) -> min(AX, BX) >= Low andalso max(AX, BX) =< High end,
    Stretches = fun(A, B) ->
                    (level_side(A, B, 1.0, z, 0.0, any) andalso Within(A, B, 1.0, 2.0))
                    orelse (level_side(A, B, 0.0, z, 1.0, any) andalso Within(A, B, 1.0, 3.0))
                    orelse level_side(A, B, 1.0, x, 3.0, any)
                    orelse (upright(A, B) andalso {element(1, A), element(3, A)} == {3.0, 1.0})
                end,
    write(filename:join(Root, "tests/homework45/bar_stretches.wings"),
          [object("Bar", BarVs, BarFs, Stretches, top_paint, true)], Materials, []),
    %% A ring of eight cubes round a hole, every edge hard: the outline of its top is two loops.
    {RingVs, RingFs} = cubes([{X, 0, Z} || X <- [0, 1, 2], Z <- [0, 1, 2], {X, Z} =/= {1, 1}], 1.0, {0.0, 0.0, 0.0}),
    write(filename:join(Root, "tests/homework45/ring.wings"),
          [object("Ring", RingVs, RingFs, All, top_paint, true)], Materials, []),
    %% Unit test files.
    {CubeVs, CubeFs} = cubes([{0, 0, 0}], 1.0, {0.0, 0.0, 0.0}),
    None = fun(_, _) -> false end,
    write(filename:join(Tests, "cube_all_hard.wings"),
          [object("Cube", CubeVs, CubeFs, All, top_paint, true)], Materials, []),
    write(filename:join(Tests, "cube_no_uvs.wings"),
          [object("Plain", CubeVs, CubeFs, None, none, false)], [], []),
    TopRing = fun(A, B) -> top_ring_and_upright(A, B, 1.0, {0.0, 0.0, 0.0}) end,
    write(filename:join(Tests, "cube_top_ring.wings"),
          [object("Ring", CubeVs, CubeFs, TopRing, top_paint, true)], Materials, []),
    OneEdge = fun(A, B) -> one_edge(A, B) end,
    write(filename:join(Tests, "cube_one_edge.wings"),
          [object("One", CubeVs, CubeFs, OneEdge, top_paint, true)], Materials, []),
    write(filename:join(Tests, "block.wings"),
          [object("Block", BlockVs, BlockFs, BlockHard, top_paint, true)], Materials, []),
    %% Two objects in one file, one named with a binary and one with characters beyond Latin-1.
    write(filename:join(Tests, "two_objects.wings"),
          [object(<<"First">>, CubeVs, CubeFs, None, none, false),
           object([16#43, 16#FC, 16#3B1], shifted(CubeVs, {3.0, 0.0, 0.0}), CubeFs, All, none, false)],
          Materials, []),
    %% An L of three cubes: its inner edges are concave.
    {LVs, LFs} = cubes([{0, 0, 0}, {1, 0, 0}, {0, 1, 0}], 1.0, {0.0, 0.0, 0.0}),
    write(filename:join(Tests, "concave_l.wings"),
          [object("L", LVs, LFs, All, none, false)], Materials, []),
    %% The same with one rim edge where the concave edge ends left sharp: one rounded and one sharp
    %% crease there, which is neither a web nor a torus piece.
    AllButOne = fun(A, B) -> lists:sort([A, B]) =/= [{1.0, 1.0, 1.0}, {2.0, 1.0, 1.0}] end,
    write(filename:join(Tests, "concave_l_one_sharp.wings"),
          [object("L", LVs, LFs, AllButOne, none, false)], Materials, []),
    %% Two layers: the L of unit cubes with a cube on its corner cube, every edge marked. The
    %% upper cube's uprights end on the lower layer's top, between two concave edges: a corner
    %% kind the rounding refuses.
    {TwoVs, TwoFs} = cubes([{0, 0, 0}, {1, 0, 0}, {0, 0, 1}, {0, 1, 0}], 1.0, {0.0, 0.0, 0.0}),
    write(filename:join(Tests, "two_layers.wings"),
          [object("Steps", TwoVs, TwoFs, All, none, false)], Materials, []),
    %% The same with only its uprights hard (for the homework program, whose test compares the
    %% two: the standing cube's top rim is rounded only in the first).
    write(filename:join(Root, "tests/homework45/two_layers_uprights.wings"),
          [object("Steps", TwoVs, TwoFs, Upright, none, false)], Materials, []),
    %% Layers of other footprints, every edge marked (for the homework program, which rounds the
    %% rims of a layer's L with nothing above or below it as it rounds a one-layer L's): an L of
    %% three cubes on a slab of 2 x 2, and the slab on the L.
    {LOnSlabVs, LOnSlabFs} = cubes([{X, 0, Z} || X <- [0, 1], Z <- [0, 1]] ++ [{0, 1, 0}, {1, 1, 0}, {0, 1, 1}], 1.0,
                                   {0.0, 0.0, 0.0}),
    write(filename:join(Root, "tests/homework45/l_on_slab.wings"),
          [object("Steps", LOnSlabVs, LOnSlabFs, All, top_paint, true)], Materials, []),
    {SlabOnLVs, SlabOnLFs} = cubes([{0, 0, 0}, {1, 0, 0}, {0, 0, 1}] ++ [{X, 1, Z} || X <- [0, 1], Z <- [0, 1]], 1.0,
                                   {0.0, 0.0, 0.0}),
    write(filename:join(Root, "tests/homework45/slab_on_l.wings"),
          [object("Steps", SlabOnLVs, SlabOnLFs, All, top_paint, true)], Materials, []),
    %% The L on the slab with the L's convex uprights sharp (its top rim meets in mitres there) and
    %% its inner upright hard.
    LSharpCorners = fun({AX, AY, AZ} = A, {_, BY, _} = B) ->
                            not (upright(A, B) andalso min(AY, BY) >= 1.0 andalso {AX, AZ} =/= {1.0, 1.0})
                    end,
    write(filename:join(Root, "tests/homework45/l_on_slab_sharp_corners.wings"),
          [object("Steps", LOnSlabVs, LOnSlabFs, LSharpCorners, top_paint, true)], Materials, []),
    %% A bar of two cubes standing inside the top of a slab of 4 x 3, every edge marked: the
    %% fillets round its foot run on past the grid line between its cubes and meet in torus
    %% pieces at its rounded uprights.
    {BarOnSlabVs, BarOnSlabFs} = cubes([{X, 0, Z} || X <- [0, 1, 2, 3], Z <- [0, 1, 2]] ++ [{1, 1, 1}, {2, 1, 1}],
                                       1.0, {0.0, 0.0, 0.0}),
    write(filename:join(Root, "tests/homework45/bar_on_slab.wings"),
          [object("Bar", BarOnSlabVs, BarOnSlabFs, fun(_, _) -> true end, top_paint, true)], Materials, []),
    %% An L of three cubes standing inside the top of a slab of 4 x 4, every edge marked: the
    %% fillets round its foot meet in torus pieces at its convex corners and in an eighth of a
    %% sphere at its concave one.
    {LInSlabVs, LInSlabFs} = cubes([{X, 0, Z} || X <- [0, 1, 2, 3], Z <- [0, 1, 2, 3]] ++ [{1, 1, 1}, {2, 1, 1}, {1, 1, 2}],
                                   1.0, {0.0, 0.0, 0.0}),
    write(filename:join(Root, "tests/homework45/l_inside_slab.wings"),
          [object("Steps", LInSlabVs, LInSlabFs, All, top_paint, true)], Materials, []),
    %% The same with the L's inner upright sharp: the fillets meet in a mitre at its foot.
    SharpInner = fun(A, B) -> not (upright(A, B) andalso {element(1, A), element(3, A)} == {2.0, 2.0}) end,
    write(filename:join(Root, "tests/homework45/l_inside_slab_sharp_inner.wings"),
          [object("Steps", LInSlabVs, LInSlabFs, SharpInner, top_paint, true)], Materials, []),
    %% A U of five cubes on a slab of 3 x 2 (two concave corners on its top), and a ring of eight
    %% on a slab of 3 x 3 (its top outlined by two loops, round the hole and round the ring).
    {UOnSlabVs, UOnSlabFs} = cubes([{X, 0, Z} || X <- [0, 1, 2], Z <- [0, 1]] ++
                                       [{0, 1, 0}, {1, 1, 0}, {2, 1, 0}, {0, 1, 1}, {2, 1, 1}], 1.0, {0.0, 0.0, 0.0}),
    write(filename:join(Root, "tests/homework45/u_on_slab.wings"),
          [object("Steps", UOnSlabVs, UOnSlabFs, All, top_paint, true)], Materials, []),
    {RingOnSlabVs, RingOnSlabFs} = cubes([{X, 0, Z} || X <- [0, 1, 2], Z <- [0, 1, 2]] ++
                                             [{X, 1, Z} || X <- [0, 1, 2], Z <- [0, 1, 2], {X, Z} =/= {1, 1}], 1.0,
                                         {0.0, 0.0, 0.0}),
    write(filename:join(Root, "tests/homework45/ring_on_slab.wings"),
          [object("Steps", RingOnSlabVs, RingOnSlabFs, All, top_paint, true)], Materials, []),
    %% A cube standing on a slab of 2 x 2 cubes at one corner, every edge marked: at the foot of
    %% its inner upright the upright meets the two fillets along its foot (a standing torus
    %% piece); at the two feet beside the slab's sides a fillet ends between two rounded convex
    %% edges (a torus piece as in the L).
    {SlabVs, SlabFs} = cubes([{X, 0, Z} || X <- [0, 1], Z <- [0, 1]] ++ [{0, 1, 0}], 1.0, {0.0, 0.0, 0.0}),
    write(filename:join(Tests, "slab_corner_cube.wings"),
          [object("Slab", SlabVs, SlabFs, All, none, false)], Materials, []),
    write(filename:join(Models, "slab_cube.wings"),
          [object("Slab", SlabVs, SlabFs, All, top_paint, true)], Materials, []),
    %% A tower of two cubes on the same corner: the upright above the standing corner runs
    %% straight on through the corner where the two cubes' sides meet.
    {TowerVs, TowerFs} = cubes([{X, 0, Z} || X <- [0, 1], Z <- [0, 1]] ++ [{0, 1, 0}, {0, 2, 0}], 1.0, {0.0, 0.0, 0.0}),
    write(filename:join(Tests, "slab_tower.wings"),
          [object("Tower", TowerVs, TowerFs, All, top_paint, true)], Materials, []),
    %% A cube in the middle of a slab of 3 x 3 cubes, every edge marked: four standing corners,
    %% joined by fillets that meet no other torus piece.
    {MiddleVs, MiddleFs} = cubes([{X, 0, Z} || X <- [0, 1, 2], Z <- [0, 1, 2]] ++ [{1, 1, 1}], 1.0, {0.0, 0.0, 0.0}),
    write(filename:join(Tests, "slab_middle_cube.wings"),
          [object("Slab", MiddleVs, MiddleFs, All, top_paint, true)], Materials, []),
    %% A cube on the end of an arm of an L of five cubes (arms two cubes long), every edge
    %% marked: the fillets along its foot end between rounded convex edges at both ends.
    {ArmVs, ArmFs} = cubes([{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 0, 1}, {0, 0, 2}, {2, 1, 0}], 1.0, {0.0, 0.0, 0.0}),
    write(filename:join(Tests, "l_arm_cube.wings"),
          [object("Arm", ArmVs, ArmFs, All, top_paint, true)], Materials, []),
    %% The same with the cube's uprights sharp: the fillets along its foot meet round each
    %% upright's foot in a horn piece.
    SharpUprights = fun({_, AY, _} = A, {_, BY, _} = B) -> not (upright(A, B) andalso min(AY, BY) >= 1.0) end,
    write(filename:join(Tests, "slab_middle_cube_sharp_uprights.wings"),
          [object("Slab", MiddleVs, MiddleFs, SharpUprights, top_paint, true)], Materials, []),
    %% The corner cube on its slab with the slab's bottom edges and its three uprights away from
    %% the cube sharp (its top rim meets in mitres there), with texture coordinates.
    SlabMixed = fun({AX, AY, AZ} = A, {_, BY, _} = B) ->
                        not (AY == 0.0 andalso BY == 0.0) andalso
                            not (upright(A, B) andalso max(AY, BY) =< 1.0 andalso {AX, AZ} =/= {0.0, 0.0})
                end,
    write(filename:join(Tests, "slab_corner_cube_mixed.wings"),
          [object("Slab", SlabVs, SlabFs, SlabMixed, top_paint, true)], Materials, []),
    %% Broken and unsupported files.
    Cube = object("Cube", CubeVs, CubeFs, All, top_paint, true),
    write_term(filename:join(Tests, "version_3.wings"), {wings, 3, {[Cube], Materials, []}}),
    write_term(filename:join(Tests, "not_a_tuple.wings"), [wings, 2]),
    {object, N, {winged, Es, Fs, Vs, He}, P} = Cube,
    write_term(filename:join(Tests, "face_out_of_range.wings"),
               {wings, 2, {[{object, N, {winged, set_face(Es, 3, 99), Fs, Vs, He}, P}], Materials, []}}),
    write_term(filename:join(Tests, "short_vertex.wings"),
               {wings, 2, {[{object, N, {winged, Es, Fs, [[<<1.0/float>>] | tl(Vs)], He}, P}], Materials, []}}),
    write_term(filename:join(Tests, "hard_edge_out_of_range.wings"),
               {wings, 2, {[{object, N, {winged, Es, Fs, Vs, [1000]}, P}], Materials, []}}),
    write_term(filename:join(Tests, "no_edge_record.wings"),
               {wings, 2, {[{object, N, {winged, [[{color_lt, <<0:96>>}] | tl(Es)], Fs, Vs, He}, P}], Materials, []}}),
    write_term(filename:join(Tests, "bad_shininess.wings"),
               {wings, 2, {[Cube], [material(shiny, {1.0, 1.0, 1.0, 1.0}, 7.0)], []}}),
    %% Overhangs for the homework program's walker: a column of three cubes with an arm of two
    %% cubes on its top (its bottom at height 2, above the walker's head, 1.8), and the same two
    %% cubes tall (the arm's bottom at height 1). Centred on x = 1, the arm along +z.
    {HighVs, HighFs} = cubes([{0, 0, -1}, {0, 1, -1}, {0, 2, -1}, {0, 2, 0}, {0, 2, 1}], 1.0, {0.5, 0.0, 0.0}),
    write(filename:join(Root, "tests/homework45/overhang_high.wings"),
          [object("Gallows", HighVs, HighFs, Upright, top_paint, true)], Materials, []),
    {LowVs, LowFs} = cubes([{0, 0, -1}, {0, 1, -1}, {0, 1, 0}, {0, 1, 1}], 1.0, {0.5, 0.0, 0.0}),
    write(filename:join(Root, "tests/homework45/overhang_low.wings"),
          [object("Gallows", LowVs, LowFs, Upright, top_paint, true)], Materials, []),
    %% Objects the homework program refuses, each naming what is wrong (tests/homework45).
    Refused = filename:join(Root, "tests/homework45"),
    {TopVs, TopFs} = cubes([{0, 0, 0}], 1.0, {0.0, 1.0, 0.0}),
    %% Two cubes stacked, each with its own vertices: the lower one's top and the upper one's
    %% bottom are two faces in one place.
    write(filename:join(Refused, "refused_overlapping_faces.wings"),
          [object("Stack", CubeVs ++ TopVs, CubeFs ++ offset_faces(TopFs, length(CubeVs)), None, none, false)],
          Materials, []),
    %% Two cubes pushed half into each other: their faces cross, and the space they share is
    %% inside twice.
    {HalfVs, HalfFs} = cubes([{0, 0, 0}], 1.0, {0.5, 0.5, 0.5}),
    write(filename:join(Refused, "refused_crossing_cubes.wings"),
          [object("Crossing", CubeVs ++ HalfVs, CubeFs ++ offset_faces(HalfFs, length(CubeVs)), None, none, false)],
          Materials, []),
    %% A cube turned inside out: every face counter-clockwise seen from inside.
    write(filename:join(Refused, "refused_inside_out.wings"),
          [object("Inverted", CubeVs, [{Normal, lists:reverse(Is)} || {Normal, Is} <- CubeFs], None, none, false)],
          Materials, []),
    %% A cube whose top face Wings3D would show as a hole (the object's holes property): open.
    {object, OpenN, OpenW, OpenP} = object("Open", CubeVs, CubeFs, All, none, false),
    TopFace = length(lists:takewhile(fun({Normal, _}) -> Normal =/= {0, 1, 0} end, CubeFs)),
    write(filename:join(Refused, "refused_open_cube.wings"),
          [{object, OpenN, OpenW, OpenP ++ [{holes, [TopFace]}]}], Materials, []),
    %% Two cubes that touch along one upright edge only, each with its own vertices.
    {DiagonalVs, DiagonalFs} = cubes([{1, 0, 1}], 1.0, {0.0, 0.0, 0.0}),
    write(filename:join(Refused, "refused_cubes_on_an_edge.wings"),
          [object("Diagonal", CubeVs ++ DiagonalVs, CubeFs ++ offset_faces(DiagonalFs, length(CubeVs)), None, none,
                  false)], Materials, []),
    %% A square seen from both sides: two faces, no volume.
    Square = [{0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}, {1.0, 0.0, 0.0}, {1.0, 0.0, 1.0}],
    write(filename:join(Refused, "refused_flat.wings"),
          [object("Flat", Square, [{{0, 1, 0}, [0, 1, 3, 2]}, {{0, -1, 0}, [0, 2, 3, 1]}], None, none, false)],
          Materials, []),
    %% Edge 0 of the cube with one face on both of its sides, and with a face it does not border
    %% on its left (that face then has edges in two planes).
    {object, _, {winged, [[First | Attributes] | OtherEdges], CubeFaces, CubeVertices, CubeHard}, _} =
        object("Cube", CubeVs, CubeFs, None, none, false),
    Broken = fun(Name, Record) ->
                     write(filename:join(Refused, Name),
                           [{object, "Cube", {winged, [[Record | Attributes] | OtherEdges], CubeFaces, CubeVertices,
                                              CubeHard}, []}], Materials, [])
             end,
    Broken("refused_face_on_both_sides.wings", setelement(5, First, element(4, First))),
    [Stranger | _] = [F || F <- lists:seq(0, 5), F =/= element(4, First), F =/= element(5, First)],
    Broken("refused_face_not_in_a_plane.wings", setelement(4, First, Stranger)),
    %% A vertex at infinity; an object without vertices; a file without objects.
    write(filename:join(Refused, "refused_infinite_vertex.wings"),
          [{object, "Cube", {winged, [[First | Attributes] | OtherEdges], CubeFaces,
                             [[<<16#7FF0000000000000:64, 0.0/float, 0.0/float>>] | tl(CubeVertices)], CubeHard}, []}],
          Materials, []),
    write(filename:join(Refused, "refused_no_vertices.wings"),
          [{object, "Empty", {winged, [], [], [], []}, []}], Materials, []),
    write(filename:join(Refused, "refused_no_objects.wings"), [], Materials, []),
    %% Every term shape the decoder reads, with each encoding Erlang offers for it.
    Shapes = {0, 255, 256, -1, 2147483647, -2147483648, 1 bsl 40, -(1 bsl 40), 1.5, -0.25,
              atom, 'ünï', "text", [1000, 2000], [], <<1, 2, 3>>, {}, #{key => value},
              list_to_tuple(lists:seq(1, 300)), lists:seq(1, 300)},
    ok = file:write_file(filename:join(Tests, "shapes.term"), term_to_binary(Shapes)),
    ok = file:write_file(filename:join(Tests, "shapes_compressed.term"), term_to_binary(Shapes, [compressed])),
    ok = file:write_file(filename:join(Tests, "shapes_old_floats.term"), term_to_binary(Shapes, [{minor_version, 0}])),
    ok.

material(Name, Diffuse, Shininess) ->
    {Name, [{maps, []},
            {opengl, [{diffuse, Diffuse}, {ambient, {0.3, 0.3, 0.3, 1.0}}, {specular, {0.2, 0.2, 0.2, 1.0}},
                      {emission, {0.0, 0.0, 0.0, 1.0}}, {shininess, Shininess}, {vertex_colors, ignore}]}]}.

%% The outside faces of a set of cubes, as {Vertices, Faces}: vertices merged, faces
%% counter-clockwise seen from outside, each {Normal, [VertexIndex]}.
cubes(Cells, Size, {OX, OY, OZ}) ->
    Sides = [{{1, 0, 0}, [{1, 0, 0}, {1, 1, 0}, {1, 1, 1}, {1, 0, 1}]},
             {{-1, 0, 0}, [{0, 0, 0}, {0, 0, 1}, {0, 1, 1}, {0, 1, 0}]},
             {{0, 1, 0}, [{0, 1, 0}, {0, 1, 1}, {1, 1, 1}, {1, 1, 0}]},
             {{0, -1, 0}, [{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}]},
             {{0, 0, 1}, [{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}]},
             {{0, 0, -1}, [{0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}]}],
    Quads = [{N, [{(X + CX) * Size + OX, (Y + CY) * Size + OY, (Z + CZ) * Size + OZ} || {CX, CY, CZ} <- Corners]}
             || {X, Y, Z} <- Cells, {{NX, NY, NZ} = N, Corners} <- Sides,
                not lists:member({X + NX, Y + NY, Z + NZ}, Cells)],
    Points = lists:usort(lists:append([Ps || {_, Ps} <- Quads])),
    Index = maps:from_list(lists:zip(Points, lists:seq(0, length(Points) - 1))),
    {Points, [{N, [maps:get(P, Index) || P <- Ps]} || {N, Ps} <- Quads]}.

%% The faces of a second set of cubes whose vertices follow Count others in one vertex list.
offset_faces(Faces, Count) -> [{N, [I + Count || I <- Is]} || {N, Is} <- Faces].

shifted(Points, {DX, DY, DZ}) -> [{X + DX, Y + DY, Z + DZ} || {X, Y, Z} <- Points].

top_ring_and_upright({AX, AY, AZ}, {BX, BY, BZ}, Top, {OX, _, OZ}) ->
    (AY == Top andalso BY == Top) orelse (AX == OX andalso BX == OX andalso AZ == OZ andalso BZ == OZ).

upright({AX, _, AZ}, {BX, _, BZ}) -> AX == BX andalso AZ == BZ.

%% An edge at height Y with coordinate Axis (x or z) equal to Value at both ends, and, unless
%% Half is any, its other coordinate (Half) at least 0 at both ends.
level_side({AX, AY, AZ}, {BX, BY, BZ}, Y, Axis, Value, Half) ->
    Coordinate = fun(x, {X, _}) -> X; (z, {_, Z}) -> Z end,
    {A, B} = {{AX, AZ}, {BX, BZ}},
    AY == Y andalso BY == Y andalso Coordinate(Axis, A) == Value andalso Coordinate(Axis, B) == Value
        andalso (Half == any orelse (Coordinate(Half, A) >= 0 andalso Coordinate(Half, B) >= 0)).

%% A top edge (y = Top) on the outside of an L of cubes of size Size from Low to Low + 2 Size in
%% x and z.
outer_top({AX, AY, AZ}, {BX, BY, BZ}, Top, Low, Size) ->
    Outside = fun(C) -> C == Low orelse C == Low + 2 * Size end,
    AY == Top andalso BY == Top andalso
        ((AX == BX andalso Outside(AX)) orelse (AZ == BZ andalso Outside(AZ))).

%% A top edge (y = Top) of a layer of cubes that has a cube on one side of it only: on the rim.
top_rim({AX, AY, AZ}, {BX, BY, BZ}, Top, Cells, Size, {OX, _, OZ}) when AY == Top, BY == Top ->
    Cell = fun(X, Z) -> lists:member({floor((X - OX) / Size), 0, floor((Z - OZ) / Size)}, Cells) end,
    {MX, MZ} = {(AX + BX) / 2, (AZ + BZ) / 2},
    {DX, DZ} = {(BZ - AZ) / 4, (AX - BX) / 4},
    Cell(MX + DX, MZ + DZ) =/= Cell(MX - DX, MZ - DZ);
top_rim(_, _, _, _, _, _) -> false.

one_edge({AX, AY, _}, {BX, BY, _}) -> AX == 1.0 andalso BX == 1.0 andalso AY == 1.0 andalso BY == 1.0.

%% The texture coordinates of a point of a face: its position across the face's plane, with t
%% up (or along -z on horizontal faces), one unit of texture to a unit of length.
uv({1, 0, 0}, {_, Y, Z}) -> {-Z, Y};
uv({-1, 0, 0}, {_, Y, Z}) -> {Z, Y};
uv({0, 0, 1}, {X, Y, _}) -> {X, Y};
uv({0, 0, -1}, {X, Y, _}) -> {-X, Y};
uv({0, 1, 0}, {X, _, Z}) -> {X, -Z};
uv({0, -1, 0}, {X, _, Z}) -> {X, Z}.

%% A Wings object from vertices and counter-clockwise faces. Edge (A -> B) belongs to the face
%% that meets it first as its left face (Vs = A, Ve = B), to the other as its right face. In a
%% face, the successor of the edge from v(k) to v(k+1) is the edge from v(k-1) to v(k) (the walk
%% by successors runs clockwise), and each edge records v(k): Vs for the left face, Ve for the
%% right, with that corner's texture coordinates as uv_lt or uv_rt.
object(Name, Points, Faces, Hard, MaterialRule, WithUvs) ->
    Position = list_to_tuple(Points),
    Loops = [Vs || {_, Vs} <- Faces],
    Directed = lists:append([pairs(Vs) || Vs <- Loops]),
    Keys = lists:foldl(fun({A, B}, Acc) ->
                               K = {min(A, B), max(A, B)},
                               case lists:keymember(K, 1, Acc) of
                                   true -> Acc;
                                   false -> Acc ++ [{K, {A, B}}]
                               end
                       end, [], Directed),
    EdgeIndex = maps:from_list(lists:zip([K || {K, _} <- Keys], lists:seq(0, length(Keys) - 1))),
    Edge = fun(A, B) -> maps:get({min(A, B), max(A, B)}, EdgeIndex) end,
    Empty = maps:from_list([{I, #{vs => A, ve => B}} || {{_, {A, B}}, I} <- lists:zip(Keys, lists:seq(0, length(Keys) - 1))]),
    Table = lists:foldl(
              fun({F, {Normal, Vs}}, T0) ->
                      N = length(Vs),
                      At = fun(K) -> lists:nth(((K rem N) + N) rem N + 1, Vs) end,
                      lists:foldl(
                        fun(K, T) ->
                                A = At(K), B = At(K + 1),
                                E = Edge(A, B),
                                Prev = Edge(At(K - 1), A),
                                Next = Edge(B, At(K + 2)),
                                UV = uv(Normal, element(A + 1, Position)),
                                R = maps:get(E, T),
                                case maps:get(vs, R) of
                                    A -> T#{E => R#{lf => F, ltsu => Prev, ltpr => Next, uv_lt => UV}};
                                    B -> T#{E => R#{rf => F, rtsu => Prev, rtpr => Next, uv_rt => UV}}
                                end
                        end, T0, lists:seq(0, N - 1))
              end, Empty, lists:zip(lists:seq(0, length(Faces) - 1), Faces)),
    Es = [edge_term(maps:get(I, Table), WithUvs) || I <- lists:seq(0, length(Keys) - 1)],
    Fs = [face_material(MaterialRule, Normal) || {Normal, _} <- Faces],
    VsTerm = [[<<X/float, Y/float, Z/float>>] || {X, Y, Z} <- Points],
    He = [I || {{_, {A, B}}, I} <- lists:zip(Keys, lists:seq(0, length(Keys) - 1)),
               Hard(element(A + 1, Position), element(B + 1, Position))],
    {object, Name, {winged, Es, Fs, VsTerm, He}, [{plugin_states, []}]}.

pairs(Vs) -> lists:zip(Vs, tl(Vs) ++ [hd(Vs)]).

edge_term(#{vs := Vs, ve := Ve, lf := Lf, rf := Rf, ltpr := Ltpr, ltsu := Ltsu, rtpr := Rtpr, rtsu := Rtsu} = R, WithUvs) ->
    Record = {edge, Vs, Ve, Lf, Rf, Ltpr, Ltsu, Rtpr, Rtsu},
    case WithUvs of
        true ->
            {U1, V1} = maps:get(uv_lt, R),
            {U2, V2} = maps:get(uv_rt, R),
            [Record, {uv_lt, <<U1/float, V1/float>>}, {uv_rt, <<U2/float, V2/float>>}];
        false -> [Record]
    end.

face_material(none, _) -> [];
face_material(top_paint, {0, 1, 0}) -> [{material, paint}];
face_material(top_paint, _) -> [{material, wood}].

set_face([First | Rest], Position, Face) -> [[setelement(Position + 1, hd(First), Face) | tl(First)] | Rest].

write(Path, Shapes, Materials, Props) -> write_term(Path, {wings, 2, {Shapes, Materials, Props}}).

write_term(Path, Term) ->
    Bin = term_to_binary(Term, [compressed]),
    ok = file:write_file(Path, <<"#!WINGS-1.0\r\n\032\04", (byte_size(Bin)):32, Bin/binary>>),
    io:format("wrote ~s~n", [Path]).
