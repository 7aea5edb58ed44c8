# The whole annular cell, small: grains sheared in a ring trough whose floor and side walls turn
# about the y axis while the flat top stays still (fixed gap; no load control yet). Mesh walls
# with LIGGGHTS' surface_ang_vel: the surfaces move, the meshes stay put, so no neighbour-list
# rebuilds for the walls and the geometry is exact up to the facets. The curvature replaces the
# slice's centripetal body force. Make the meshes and grains first:
#   python3 make_ring.py            (defaults: 10 d radius, 4 d wide, 4 d gap, ~770 grains)
#   granlub-liggghts -in in.ring    (~10 s)
# Output: torques.txt, each wall's force along the axis and torque about it, averaged over
# 2000-step windows from every step (an impulse force lasts one step: sampling every Nth step
# would miss most of them); final.txt, the grains at the end.
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
pair_style gran model impulse tangential impulse
pair_coeff * *
timestep 5e-6
fix floor all mesh/surface/stress file floor.stl type 1 surface_ang_vel origin 0 0 0 axis 0 1 0 omega ${Omega}
fix inner all mesh/surface/stress file inner.stl type 1 surface_ang_vel origin 0 0 0 axis 0 1 0 omega ${Omega}
fix outer all mesh/surface/stress file outer.stl type 1 surface_ang_vel origin 0 0 0 axis 0 1 0 omega ${Omega}
fix top all mesh/surface/stress file top.stl type 1
fix walls all wall/gran model impulse tangential impulse mesh n_meshes 4 meshes floor inner outer top
fix grav all gravity 9.81 vector 0 -1 0
fix integr all nve/sphere
# columns: step, then for floor, inner, outer, top: force along y and torque about y (N, N m), window means
fix sums all ave/time 1 2000 2000 f_floor[2] f_floor[5] f_inner[2] f_inner[5] f_outer[2] f_outer[5] f_top[2] f_top[5] ave one file torques.txt
variable r atom sqrt(x*x+z*z)
compute rmean all reduce ave v_r
thermo_style custom step atoms ke c_rmean
thermo 2000
run 20000
write_dump all custom final.txt id x y z radius vx vy vz
