# c12-B4: how fast must a bike with its rider go to have the momentum of a car ten times as
# heavy driving at 60 km/h? Expected 600 km/h. Exercises: mechkit solve (equal momenta
# m_bike v_bike = m_car v_car; speeds in km/h, masses relative to the bike's).
mechkit solve "m_bike*v_bike = m_car*v_car" --for v_bike --set m_bike=1,m_car=10,v_car=60 --json
#> answer = /numeric/0
