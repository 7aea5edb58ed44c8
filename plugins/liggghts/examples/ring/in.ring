# The whole annular cell, small: grains sheared in a ring trough whose floor and side walls turn
# about the y axis while the flat annular top is held at a normal stress P (load control, as the
# experiment's weighted disc). Mesh walls with LIGGGHTS' surface_ang_vel: the surfaces move, the
# meshes stay put, so no neighbour-list rebuilds for the walls and the geometry is exact up to the
# facets. The curvature replaces the slice's centripetal body force. Make the meshes and grains first:
#   python3 make_ring.py            (defaults: 10 d radius, 4 d wide, 4 d gap, ~770 grains, 5.5 kPa)
#   granlub-liggghts -in in.ring    (~20 s; -var windows N for N servo windows of 100 steps, default 200)
#   python3 ring_stats.py           (wall stresses, gap, balances, profiles; --from T: steady from T s)
# Output: torques.txt, each wall's force along the axis and torque about it, averaged over
# 2000-step windows from every step (an impulse force lasts one step: sampling every Nth step
# would miss most of them); radial.txt, the grains' mean radius and how many lie beyond R, per
# window; plate.txt, the top's position and stress per servo window;
# final.txt, the grains at the end.
atom_style sphere
atom_modify map array
boundary f f f
newton off
communicate single vel yes
units si
read_data grains.data
include ring.vars
neighbor 0.0002 bin
neigh_modify delay 0
hard_particles yes
fix m1 all property/global youngsModulus peratomtype 1e9
fix m2 all property/global poissonsRatio peratomtype 0.25
fix m3 all property/global coefficientRestitution peratomtypepair 1 0.9
fix m4 all property/global coefficientFriction peratomtypepair 1 0.5
# iterate off: Sawyer & Tichy's single pass, as granlub's sheared cases run it (the models' default,
# iterate on, solves the contacts together: it brings piles to rest, at several times the cost)
pair_style gran model impulse tangential impulse iterate off
pair_coeff * *
timestep 5e-6
fix floor all mesh/surface/stress file floor.stl type 1 surface_ang_vel origin 0 0 0 axis 0 1 0 omega ${Omega}
fix inner all mesh/surface/stress file inner.stl type 1 surface_ang_vel origin 0 0 0 axis 0 1 0 omega ${Omega}
fix outer all mesh/surface/stress file outer.stl type 1 surface_ang_vel origin 0 0 0 axis 0 1 0 omega ${Omega}
fix top all mesh/surface/stress file top.stl type 1
fix walls all wall/gran model impulse tangential impulse mesh n_meshes 4 meshes floor inner outer top iterate off
# the top moves along the axis at v_vtop, set by the servo below (starts at y = H, at rest)
variable hplate equal ${H}
variable zero equal 0
variable vtop equal 0
fix lift all move/mesh mesh top linear/variable v_zero v_vtop v_zero
fix grav all gravity 9.81 vector 0 -1 0
fix integr all nve/sphere
# columns: step, then for floor, inner, outer, top: force along y and torque about y (N, N m), window means
fix sums all ave/time 1 2000 2000 f_floor[2] f_floor[5] f_inner[2] f_inner[5] f_outer[2] f_outer[5] f_top[2] f_top[5] ave one file torques.txt
# the radial distribution: mean radius and grains beyond R, averaged every 10 steps over the windows
variable r atom sqrt(x*x+z*z)
variable beyond atom v_r>${R}
compute rmean all reduce ave v_r
compute nout all reduce sum v_beyond
fix radial all ave/time 10 200 2000 c_rmean c_nout file radial.txt
thermo_style custom step atoms ke c_rmean v_hplate
thermo 2000
thermo_modify norm no lost error

# Load control with the slice's rule (plugins/liggghts/README.md, "Load control"): every 100 steps
# the top's stress over those steps, P_w = F_y/A (the force summed every step), sets the plate's
# next position, h + 0.05 d clamp((P_w - P)/P, -1, 3) kept in [hmin, hmax], which it reaches
# moving steadily over the next 100 steps. An integral controller: in steady state the mean of P_w
# is P. Not the slice's jumps: re-making the top mesh at its new place each window left 14 % of
# the grains' weight out of the walls' recorded forces; a moving mesh keeps the books
# (README, "The whole ring"). plate.txt: step, plate position (m), P_w (Pa).
# -var dump_every N: the grains every N steps in prof.<step>.txt (ring_stats.py's radial and gap profiles)
variable dump_every index 0
if "${dump_every} > 0" then "dump prof all custom ${dump_every} prof.*.txt id x y z vx vy vz"
fix servoF all ave/time 1 100 100 f_top[2]
variable ptop equal f_servoF/${A}
variable err equal (v_ptop-${P})/${P}
variable errc equal v_err*(v_err>=-1)*(v_err<=3)+3*(v_err>3)-(v_err<-1)
variable htry equal v_hplate+0.05*${d}*v_errc
variable hnew equal v_htry*(v_htry>=${hmin})*(v_htry<=${hmax})+${hmin}*(v_htry<${hmin})+${hmax}*(v_htry>${hmax})
fix plate all ave/time 100 1 100 v_hplate v_ptop file plate.txt
variable windows index 200
variable update loop ${windows}
label servo
run 100 post no
variable vtop equal (${hnew}-${hplate})/(100*dt)
variable hplate equal ${hnew}
next update
jump SELF servo
write_dump all custom final.txt id x y z radius vx vy vz
