methods ,
